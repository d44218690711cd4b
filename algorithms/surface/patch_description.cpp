// JSON description -> PatchSurface3 (patch_description.hpp).
#include "algorithms/surface/patch_description.hpp"

#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {
namespace {

class Fields {
 public:
  Fields(const JsonValue::Object& object, std::string type) : object_(object), type_(std::move(type)) {}

  // Every key known to the type, or InputError naming the first other.
  void only(std::set<std::string> keys) const {
    keys.insert("type");
    for (const auto& [key, value] : object_)
      if (!keys.contains(key)) throw InputError("patch: unknown key '" + key + "' for a " + type_);
  }
  const JsonValue* find(const std::string& key) const {
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &it->second;
  }
  double number(const std::string& key, std::optional<double> fallback = std::nullopt) const {
    const JsonValue* v = find(key);
    if (!v) {
      if (fallback) return *fallback;
      throw InputError("patch: a " + type_ + " needs '" + key + "'");
    }
    if (!v->is_number()) throw InputError("patch: '" + key + "' of a " + type_ + " must be a number");
    return v->number();
  }
  std::vector<double> numbers(const std::string& key, std::size_t count, std::optional<std::vector<double>> fallback = std::nullopt) const {
    const JsonValue* v = find(key);
    if (!v) {
      if (fallback) return *fallback;
      throw InputError("patch: a " + type_ + " needs '" + key + "'");
    }
    return list(*v, key, count);
  }
  std::vector<double> list(const JsonValue& v, const std::string& key, std::size_t count) const {
    if (!v.is_array()) throw InputError("patch: '" + key + "' of a " + type_ + " must be an array of numbers");
    std::vector<double> out;
    for (const JsonValue& x : v.array()) {
      if (!x.is_number()) throw InputError("patch: '" + key + "' of a " + type_ + " must hold numbers only");
      out.push_back(x.number());
    }
    if (count != 0 && out.size() != count)
      throw InputError("patch: '" + key + "' of a " + type_ + " must hold " + std::to_string(count) + " numbers, not " +
                       std::to_string(out.size()));
    return out;
  }
  Vec3 vec3(const std::string& key, std::optional<Vec3> fallback = std::nullopt) const {
    if (!find(key) && fallback) return *fallback;
    const std::vector<double> x = numbers(key, 3);
    return {x[0], x[1], x[2]};
  }
  Vec2 vec2(const std::string& key) const {
    const std::vector<double> x = numbers(key, 2);
    return {x[0], x[1]};
  }
  std::uint32_t count(double x, const std::string& key) const {
    if (!(x >= 0.0 && x <= 1e6 && x == std::floor(x)))
      throw InputError("patch: '" + key + "' of a " + type_ + " must hold whole numbers in [0, 1e6]");
    return static_cast<std::uint32_t>(x);
  }

 private:
  const JsonValue::Object& object_;
  std::string type_;
};

}  // namespace

PatchSurface3 patch_from_description(const JsonValue& description) {
  if (!description.is_object()) throw InputError("patch: the description must be a JSON object");
  const auto& object = description.object();
  const auto type_it = object.find("type");
  if (type_it == object.end() || !type_it->second.is_string()) throw InputError("patch: give its \"type\" (a string)");
  const std::string& type = type_it->second.string();
  const Fields f(object, type);
  const Vec3 origin{0, 0, 0}, z{0, 0, 1};
  if (type == "plane") {
    f.only({"origin", "e1", "e2", "u", "v"});
    const Vec2 u = f.vec2("u"), v = f.vec2("v");
    return PatchSurface3::plane(f.vec3("origin", origin), f.vec3("e1"), f.vec3("e2"), {u.x, v.x}, {u.y, v.y});
  }
  if (type == "sphere") {
    f.only({"centre", "radius"});
    return PatchSurface3::sphere(f.vec3("centre", origin), f.number("radius"));
  }
  if (type == "cylinder") {
    f.only({"centre", "axis", "radius", "height"});
    return PatchSurface3::cylinder(f.vec3("centre", origin), f.vec3("axis", z), f.number("radius"), f.number("height"));
  }
  if (type == "cone") {
    f.only({"centre", "axis", "radius0", "radius1", "height"});
    return PatchSurface3::cone(f.vec3("centre", origin), f.vec3("axis", z), f.number("radius0"), f.number("radius1"),
                               f.number("height"));
  }
  if (type == "torus") {
    f.only({"centre", "axis", "major", "minor"});
    return PatchSurface3::torus(f.vec3("centre", origin), f.vec3("axis", z), f.number("major"), f.number("minor"));
  }
  if (type == "sine_graph") {
    f.only({"amplitude", "frequency", "radius"});
    const std::vector<double> fr = f.numbers("frequency", 2, std::vector<double>{2.0, 2.0});
    return PatchSurface3::sine_graph(f.number("amplitude", 3.0), fr[0], fr[1], f.number("radius", 3.0));
  }
  if (type == "bspline") {
    f.only({"degree", "count", "controls", "knots_u", "knots_v"});
    const std::vector<double> degree = f.numbers("degree", 2), count = f.numbers("count", 2);
    const JsonValue* controls = f.find("controls");
    if (!controls || !controls->is_array()) throw InputError("patch: a bspline needs 'controls', an array of [x, y, z]");
    std::vector<Vec3> points;
    for (const JsonValue& c : controls->array()) {
      const std::vector<double> x = f.list(c, "controls", 3);
      points.push_back({x[0], x[1], x[2]});
    }
    const std::vector<double> ku = f.numbers("knots_u", 0), kv = f.numbers("knots_v", 0);
    Patch3 patch = Patch3::bspline(std::move(points), f.count(count[0], "count"), f.count(count[1], "count"), ku, kv,
                                   f.count(degree[0], "degree"), f.count(degree[1], "degree"));
    return PatchSurface3::bspline(std::move(patch), {ku.front(), kv.front()}, {ku.back(), kv.back()});
  }
  throw InputError("unknown patch type '" + type + "' (known: plane, sphere, cylinder, cone, torus, sine_graph, bspline)");
}

}  // namespace dtlab
