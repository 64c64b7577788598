// The reference directions of the real clip's pose_squats.keypoints.tsv for the pose tests: per
// frame, left upper and fore, right upper and fore (its columns 14-17). A file that cannot be
// read, or a short line, is a test failure.
#pragma once

#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace armmimic::test {

inline std::map<int, std::array<double, 4>> ReadReferenceDirections(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::map<int, std::array<double, 4>> ref;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("frame", 0) == 0) continue;
    std::istringstream fields(line);
    int frame;
    double v;
    fields >> frame;
    for (int i = 0; i < 12; ++i) fields >> v;  // the joints' pixels
    std::array<double, 4> deg{};
    for (double& d : deg) fields >> d;
    EXPECT_TRUE(fields) << path << ": frame " << frame;
    ref[frame] = deg;
  }
  return ref;
}

}  // namespace armmimic::test
