// Shared GoogleTest main: fixes every PRNG seed so that test runs repeat exactly.
#include <clocale>
#include <cstdlib>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

int main(int argc, char** argv) {
  std::srand(0x5eed);
  cv::theRNG().state = 0x5eed;
  cv::setNumThreads(1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
