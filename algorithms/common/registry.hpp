// One registry of named variants, for every kind of pluggable piece of dtlab: Delaunay variants
// (2D, 3D), constrained methods (2D, 3D), field point methods of the meshers (2D, 3D). An entry
// is a plain struct with at least `name` and `description` (string views on static text) and
// its entry point; the registry keeps them in registration order. Each capability's built-in
// registry is a constant table (its registry.cpp), with no global state to mutate: a program or
// a test that wants one more entry copies it and add()s to the copy (docs/architecture.md,
// "Where a new X goes"); add() may move the entries, so pointers from find() are valid until the
// next add().
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

// The usual entry: a name, a line of what it does, and its entry point, a function of type `Run`.
template <class Run>
struct NamedEntry {
  std::string_view name;
  std::string_view description;
  Run* run;
};

template <class Entry>
class Registry {
 public:
  // `kind` names what the entries are in messages: "unknown <kind> 'x' (known: a, b)".
  Registry(std::string_view kind, std::initializer_list<Entry> built_in) : kind_(kind) {
    for (const Entry& e : built_in) add(e);
  }

  // Adds `entry` after the others; InputError if its name is empty or already taken.
  void add(const Entry& entry) {
    if (entry.name.empty()) throw InputError("a " + kind_ + " needs a name");
    if (find(entry.name) != nullptr) throw InputError("a " + kind_ + " named '" + std::string(entry.name) + "' exists already");
    entries_.push_back(entry);
  }

  std::span<const Entry> entries() const noexcept { return entries_; }
  auto begin() const noexcept { return entries_.begin(); }
  auto end() const noexcept { return entries_.end(); }
  std::size_t size() const noexcept { return entries_.size(); }
  bool empty() const noexcept { return entries_.empty(); }
  const Entry& front() const noexcept { return entries_.front(); }  // the reference entry of a family

  // The entry called `name`, or nullptr.
  const Entry* find(std::string_view name) const noexcept {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }

  // The entry called `name`; InputError naming it and the known ones otherwise.
  const Entry& at(std::string_view name) const {
    if (const Entry* e = find(name)) return *e;
    throw InputError("unknown " + kind_ + " '" + std::string(name) + "' (known: " + names(", ") + ")");
  }

  // The names in order, joined by `separator`.
  std::string names(std::string_view separator) const {
    std::string out;
    for (const Entry& e : entries_) {
      if (!out.empty()) out += separator;
      out += e.name;
    }
    return out;
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace dtlab
