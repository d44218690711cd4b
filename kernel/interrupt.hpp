// Cooperative interruption of a long run: the caller hands over a check, the algorithm asks it
// between its phases, passes and rounds and, when it answers yes, stops by throwing Interrupted
// (nothing half-built is returned). The Python module's check runs the interpreter's signal
// handlers, so that Ctrl-C during dtlab.mesh raises KeyboardInterrupt at the next phase
// (python/src/module.cpp); without a check nothing is asked and nothing costs.
#pragma once

#include <functional>
#include <string>

#include "kernel/error.hpp"

namespace dtlab {

using InterruptCheck = std::function<bool()>;

// `where` names the point reached ("mesh2d: after the control space"), for the message.
class Interrupted : public Error {
 public:
  explicit Interrupted(const std::string& where) : Error("interrupted " + where) {}
};

inline void poll_interrupt(const InterruptCheck& check, const char* where) {
  if (check && check()) throw Interrupted(where);
}

}  // namespace dtlab
