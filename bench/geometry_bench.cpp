// Per-frame cost of the chapter 3 geometry at the engines' working size, 320x240. The engines
// must run at >= 1000 frames/s, so each of these has to stay well under a millisecond.
// OpenCV's equivalents are timed alongside for reference.
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgproc.hpp>

#include "armmimic/core/geometry.h"

namespace {

using namespace armmimic;

const cv::Size kSize(320, 240);

// A body and a bent arm, as the background-subtraction engine's threshold mask shows them.
cv::Mat ArmMask() {
  cv::Mat mask(kSize, CV_8UC1, cv::Scalar(0));
  cv::ellipse(mask, {110, 130}, {28, 70}, 0, 0, 360, cv::Scalar(255), cv::FILLED);
  cv::line(mask, {130, 80}, {185, 130}, cv::Scalar(255), 16);
  cv::line(mask, {185, 130}, {250, 85}, cv::Scalar(255), 13);
  cv::circle(mask, {252, 82}, 9, cv::Scalar(255), cv::FILLED);
  return mask;
}

// The same mask with salt-and-pepper noise, as before the median filter.
cv::Mat NoisyGray() {
  cv::Mat gray = ArmMask();
  cv::RNG rng(1);
  for (int i = 0; i < 800; ++i) {
    gray.at<uint8_t>(rng.uniform(0, kSize.height), rng.uniform(0, kSize.width)) =
        static_cast<uint8_t>(rng.uniform(0, 256));
  }
  return gray;
}

std::vector<cv::Point> ArmContour() {
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(ArmMask(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  return contours.front();
}

void BM_Moments(benchmark::State& state) {
  const cv::Mat mask = ArmMask();
  for (auto _ : state) benchmark::DoNotOptimize(ComputeMoments(mask));
}
BENCHMARK(BM_Moments);

void BM_MomentsOrientationSemiAxes(benchmark::State& state) {
  const cv::Mat mask = ArmMask();
  for (auto _ : state) {
    const RegionMoments m = ComputeMoments(mask, cv::Rect(140, 60, 180, 100));
    benchmark::DoNotOptimize(OrientationDeg(m));
    benchmark::DoNotOptimize(ComputeSemiAxes(m));
  }
}
BENCHMARK(BM_MomentsOrientationSemiAxes);

void BM_OpenCvMoments(benchmark::State& state) {
  const cv::Mat mask = ArmMask();
  for (auto _ : state) benchmark::DoNotOptimize(cv::moments(mask, true));
}
BENCHMARK(BM_OpenCvMoments);

void BM_ConvexHull(benchmark::State& state) {
  const std::vector<cv::Point> contour = ArmContour();
  state.counters["points"] = static_cast<double>(contour.size());
  for (auto _ : state) benchmark::DoNotOptimize(ConvexHullIndices(contour));
}
BENCHMARK(BM_ConvexHull);

void BM_OpenCvConvexHull(benchmark::State& state) {
  const std::vector<cv::Point> contour = ArmContour();
  std::vector<int> hull;
  for (auto _ : state) {
    cv::convexHull(contour, hull, false, false);
    benchmark::DoNotOptimize(hull.data());
  }
}
BENCHMARK(BM_OpenCvConvexHull);

void BM_ConvexityDefects(benchmark::State& state) {
  const std::vector<cv::Point> contour = ArmContour();
  const std::vector<int> hull = ConvexHullIndices(contour);
  for (auto _ : state) benchmark::DoNotOptimize(ConvexityDefects(contour, hull));
}
BENCHMARK(BM_ConvexityDefects);

void BM_MaskComponents(benchmark::State& state) {
  const cv::Mat mask = NoisyGray() > 0;
  cv::Mat labels;
  for (auto _ : state) benchmark::DoNotOptimize(MaskComponents(mask, &labels));
}
BENCHMARK(BM_MaskComponents);

void BM_FloodFillComponents(benchmark::State& state) {
  const cv::Mat gray = NoisyGray();
  cv::Mat labels;
  for (auto _ : state) benchmark::DoNotOptimize(FloodFillComponents(gray, 200, 255, 30, &labels));
}
BENCHMARK(BM_FloodFillComponents);

void BM_OpenCvConnectedComponents4(benchmark::State& state) {
  const cv::Mat mask = NoisyGray() > 0;
  cv::Mat labels, stats, centroids;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        cv::connectedComponentsWithStats(mask, labels, stats, centroids, 4, CV_32S));
  }
}
BENCHMARK(BM_OpenCvConnectedComponents4);

void BM_Median(benchmark::State& state) {
  const cv::Mat gray = NoisyGray();
  cv::Mat out;
  const int k = static_cast<int>(state.range(0));
  for (auto _ : state) {
    MedianFilter(gray, k, &out);
    benchmark::DoNotOptimize(out.data);
  }
}
BENCHMARK(BM_Median)->Arg(3)->Arg(5);

void BM_OpenCvMedianBlur(benchmark::State& state) {
  const cv::Mat gray = NoisyGray();
  cv::Mat out;
  const int k = static_cast<int>(state.range(0));
  for (auto _ : state) {
    cv::medianBlur(gray, out, k);
    benchmark::DoNotOptimize(out.data);
  }
}
BENCHMARK(BM_OpenCvMedianBlur)->Arg(3)->Arg(5);

// One frame's geometry as an arm engine chains it: median, components, moments, hull, defects.
void BM_FrameChain(benchmark::State& state) {
  const cv::Mat gray = NoisyGray();
  const std::vector<cv::Point> contour = ArmContour();
  cv::Mat clean, labels;
  for (auto _ : state) {
    MedianFilter(gray, 3, &clean);
    const std::vector<Component> comps = MaskComponents(clean, &labels);
    const RegionMoments m = ComputeMoments(clean);
    benchmark::DoNotOptimize(OrientationDeg(m));
    const std::vector<int> hull = ConvexHullIndices(contour);
    benchmark::DoNotOptimize(ConvexityDefects(contour, hull));
    benchmark::DoNotOptimize(comps.size());
  }
}
BENCHMARK(BM_FrameChain);

}  // namespace

BENCHMARK_MAIN();
