// Plain point files: one point per line, its coordinates separated by blanks ("x y" in 2D,
// "x y z" in 3D). Blank lines and '#' comments are allowed; every other line must hold exactly
// the dimension's count of finite numbers in the supported coordinate range, or the reader
// throws ParseError naming the line.
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "kernel/vec.hpp"

namespace dtlab {

// `file_name` names the input in error messages.
std::vector<Vec2> read_point_file2(std::istream& in, const std::string& file_name);
std::vector<Vec2> read_point_file2(const std::string& path);
std::vector<Vec3> read_point_file3(std::istream& in, const std::string& file_name);
std::vector<Vec3> read_point_file3(const std::string& path);

// 2 or 3: the number of fields on the first point line. Reads only up to that line; the
// readers above then check every line. A file without a point line is a ParseError.
int point_file_dimension(std::istream& in, const std::string& file_name);
int point_file_dimension(const std::string& path);

// Coordinates in the shortest form that reads back to the same doubles.
void write_point_file(std::ostream& out, std::span<const Vec2> points);
void write_point_file(std::ostream& out, std::span<const Vec3> points);
void write_point_file(const std::string& path, std::span<const Vec2> points);
void write_point_file(const std::string& path, std::span<const Vec3> points);

}  // namespace dtlab
