// Shared by the serial end-to-end and fault tests: a small timed VAL program with known targets,
// and emulator options that run motions fast.
#pragma once

#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/sim/pty_server.h"

namespace armmimic::test {

struct Program {
  std::string text;
  std::vector<robot::JointArray> targets;
};

// "SPEED 50" then one timed move per target, 1 s apart: move i is on file line 5 + 2 i.
inline Program MakeTimedProgram(int moves, const std::string& source,
                                const std::function<robot::JointArray(int)>& target) {
  Program p;
  std::ostringstream s;
  s << "; armmimic VAL program v1\n; source=" << source << "\nSPEED 50\n";
  for (int i = 0; i < moves; ++i) {
    const robot::JointArray t = target(i);
    p.targets.push_back(t);
    s << "; t=" << i << ".000\nDO MOVE #PPOINT(";
    for (int j = 0; j < robot::kJoints; ++j) s << (j ? "," : "") << FormatNumber(t[j], 2);
    s << ")\n";
  }
  p.text = s.str();
  return p;
}

// Motions at 1/50 of their real duration.
inline sim::EmulatorOptions Fast() {
  sim::EmulatorOptions o;
  o.time_scale = 0.02;
  return o;
}

}  // namespace armmimic::test
