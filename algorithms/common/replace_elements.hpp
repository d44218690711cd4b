// The replacement of a set of elements by new ones over the same outer boundary, once for the
// 2D and 3D optimization operators (book §8.6.1's "effective application"; callers decide on
// coordinates, this only rewires): outer facets recorded, old elements removed, new ones added,
// each new facet linked to the outer facet it repeats, else to its copy in another new element.
// Side, per dimension (optimize2d/local.cpp, optimize3d/local.cpp): kFacets, facet, element_of,
// Key, key (equal for a new facet and the outer one it repeats), mate (its copy's key), ref,
// set_outer, remove, add; kWho, kElement, describe for messages. Quadratic: sets are small.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/error.hpp"

namespace dtlab {

// `link_inner(h, key)` sets the constraint of new facet h, just linked to another new one.
template <class Side, class Mesh, class New, class LinkInner>
void replace_elements(Mesh& mesh, std::span<const std::uint32_t> old_elements, std::span<const New> new_elements,
                      std::vector<std::uint32_t>& slots, const LinkInner& link_inner) {
  struct Outer {
    typename Side::Key key;
    std::uint32_t twin;
    bool constrained;
    int ref;
    bool used;
  };
  std::vector<Outer> outer;
  auto is_old = [&](std::uint32_t t) {
    return std::find(old_elements.begin(), old_elements.end(), t) != old_elements.end();
  };
  for (const std::uint32_t t : old_elements) {
    DTLAB_ASSERT(mesh.is_alive(t));
    for (std::uint32_t i = 0; i < Side::kFacets; ++i) {
      const std::uint32_t h = Side::facet(t, i);
      const std::uint32_t g = mesh.twin(h);
      if (is_old(Side::element_of(g))) continue;
      outer.push_back({Side::key(mesh, h), g, mesh.is_constrained(h), Side::ref(mesh, h), false});
    }
  }
  for (const std::uint32_t t : old_elements) Side::remove(mesh, t);
  slots.clear();
  for (const New& n : new_elements) slots.push_back(Side::add(mesh, n));
  for (std::size_t k = 0; k < slots.size(); ++k) {
    for (std::uint32_t i = 0; i < Side::kFacets; ++i) {
      const std::uint32_t h = Side::facet(slots[k], i);
      if (mesh.twin(h) != Mesh::kNone) continue;
      const typename Side::Key key = Side::key(mesh, h), mate = Side::mate(key);
      bool linked = false;
      for (Outer& o : outer) {
        if (o.used || o.key != key) continue;
        mesh.link(h, o.twin);
        Side::set_outer(mesh, h, o.constrained, o.ref);
        o.used = true;
        linked = true;
        break;
      }
      for (std::size_t m = k + 1; !linked && m < slots.size(); ++m) {
        for (std::uint32_t j = 0; j < Side::kFacets && !linked; ++j) {
          const std::uint32_t g = Side::facet(slots[m], j);
          if (mesh.twin(g) != Mesh::kNone || Side::key(mesh, g) != mate) continue;
          mesh.link(h, g);
          link_inner(h, key);
          linked = true;
        }
      }
      if (!linked) {
        throw InternalError(std::string(Side::kWho) + ": new " + Side::describe(key) +
                            " matches neither the outer boundary nor another new " + Side::kElement);
      }
    }
  }
  for (const Outer& o : outer) {
    if (!o.used) {
      throw InternalError(std::string(Side::kWho) + ": outer " + Side::describe(o.key) + " is left without a " +
                          Side::kElement);
    }
  }
}

}  // namespace dtlab
