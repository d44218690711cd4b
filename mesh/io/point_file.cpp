#include "mesh/io/point_file.hpp"

#include <algorithm>

#include "kernel/error.hpp"
#include "mesh/io/text_input.hpp"
#include "mesh/io/text_output.hpp"

namespace dtlab {

namespace {

template <class P, std::size_t D>
std::vector<P> read_points(std::istream& stream, const std::string& file_name) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  io::LineTokenizer in(stream, file_name);
  std::vector<P> points;
  while (in.next_line()) {
    const std::string what = "point " + std::to_string(points.size() + 1);
    if (in.size() != D) {
      in.fail(what + ": expected " + std::to_string(D) + " coordinates, found " + std::to_string(in.size()) +
              " fields" + (in.size() == 5 - D ? " (a " + std::to_string(5 - D) + "D point file?)" : ""));
    }
    double c[3] = {0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < D; ++k) {
      c[k] = in.real(k, what + " " + kAxes[k]);
      io::check_coordinate(in, c[k], what + " " + kAxes[k]);
    }
    if constexpr (D == 2) {
      points.push_back(Vec2{c[0], c[1]});
    } else {
      points.push_back(Vec3{c[0], c[1], c[2]});
    }
  }
  return points;
}

void append_point(std::string& text, const Vec2& p) {
  io::append_real(text, p.x);
  text += ' ';
  io::append_real(text, p.y);
  text += '\n';
}

void append_point(std::string& text, const Vec3& p) {
  io::append_real(text, p.x);
  text += ' ';
  io::append_real(text, p.y);
  text += ' ';
  io::append_real(text, p.z);
  text += '\n';
}

template <class P>
void write_points(std::ostream& out, std::span<const P> points) {
  std::string text;
  for (const P& p : points) append_point(text, p);
  out << text;
}

template <class P>
void write_points(const std::string& path, std::span<const P> points) {
  std::ofstream out = io::open_for_writing(path);
  write_points(out, points);
  out.flush();
  io::check_written(out, path);
}

}  // namespace

std::vector<Vec2> read_point_file2(std::istream& in, const std::string& file_name) {
  return read_points<Vec2, 2>(in, file_name);
}

std::vector<Vec3> read_point_file3(std::istream& in, const std::string& file_name) {
  return read_points<Vec3, 3>(in, file_name);
}

std::vector<Vec2> read_point_file2(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_point_file2(in, path);
}

std::vector<Vec3> read_point_file3(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return read_point_file3(in, path);
}

int point_file_dimension(std::istream& stream, const std::string& file_name) {
  io::LineTokenizer in(stream, file_name);
  if (!in.next_line()) in.fail_at(std::max<std::uint64_t>(in.line(), 1), "no point in the file");
  if (in.size() != 2 && in.size() != 3) {
    in.fail("first point has " + std::to_string(in.size()) + " fields; a point file has 2 or 3 per line");
  }
  for (std::size_t k = 0; k < in.size(); ++k) in.real(k, "first point coordinate " + std::to_string(k + 1));
  return static_cast<int>(in.size());
}

int point_file_dimension(const std::string& path) {
  std::ifstream in = io::open_for_reading(path);
  return point_file_dimension(in, path);
}

void write_point_file(std::ostream& out, std::span<const Vec2> points) { write_points(out, points); }
void write_point_file(std::ostream& out, std::span<const Vec3> points) { write_points(out, points); }
void write_point_file(const std::string& path, std::span<const Vec2> points) { write_points(path, points); }
void write_point_file(const std::string& path, std::span<const Vec3> points) { write_points(path, points); }

}  // namespace dtlab
