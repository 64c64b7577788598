// LostReasons: why a run's rows were lost, counted. Each `lost` row's note is reduced to its
// reason (the text before any detail in brackets, numbers written as N, so that "jump of 150 deg
// in 0.250 s" and "jump of 96 deg in 0.167 s" count together) and tallied; the shells print the
// most frequent ones after a run, so an operator sees what the coverage went to.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/engines/measurement.h"

namespace armmimic {

class LostReasons {
 public:
  // How many reasons the shells' end-of-run reports name (the CLI's and the desktop
  // application's alike).
  static constexpr std::size_t kReported = 3;

  // Counts the lost rows of `m` (each arm's, with the pose engine's side both).
  void Add(const ArmMeasurement& m);
  int lost() const;  // the lost rows counted
  // The reasons, most frequent first (ties in alphabetical order).
  std::vector<std::pair<std::string, int>> Ranked() const;
  // One line, the `top` most frequent reasons with their rows: "the forearm lies on pixels that
  // show no arm now (81); re-acquiring (6); 2 other reasons (3)".
  // Empty when no row was lost.
  std::string Text(std::size_t top) const;

  // A note's reason: cut before " (" or "; " and numbers written as N; "no reason given" when
  // the note is empty.
  static std::string Reason(const std::string& note);

 private:
  std::map<std::string, int> counts_;
};

}  // namespace armmimic
