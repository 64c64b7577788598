// Background-subtraction engine, default path: the per-pixel model of the scene. The empty room
// (the mean of the background frames) and the standstill (the mean of the standstill frames and
// each pixel's noise over them). A pixel differs from a reference when a colour channel is off by
// more than that pixel's noise allows. Before comparing, the light is matched: a frame's gain over
// the standstill is measured per colour channel in blocks of the image (robust medians), smoothed
// and interpolated, so that a lighting drift, a flicker, a colour cast or a soft shadow passing
// over the wall and the person changes the reference instead of making the pixels differ. The
// calibration's differences (the standstill's standing body, the arm-length image's straight arm)
// leave out the room in shadow: a sharp shadow on a wall just behind is narrower than those
// blocks, and would widen the body and lengthen the arm. A pixel darker than the reference by one
// factor in every channel, over a patch whose texture the reference shows and the image keeps,
// is such a shadow, and so is a region of such pixels whose textured pixels keep it. On a plain
// wall a shadow cannot be told from a sleeve of the wall's colour, and still differs.
// Private to src/engines.
#pragma once

#include <opencv2/core.hpp>

namespace armmimic::bgsub {

class PixelModel {
 public:
  // Starts a standstill of `size` frames' size.
  void Begin(const cv::Size& size);
  void AddStandstill(const cv::Mat& bgr);  // CV_8UC3
  // After the last standstill frame: the means, the noise and the per-pixel thresholds. A
  // difference over `cap` always counts (the thesis' threshold); `background` is CV_8UC3.
  void Finish(const cv::Mat& background, int cap);
  bool ready() const { return !threshold_.empty(); }

  const cv::Mat& background() const { return background_; }
  const cv::Mat& standstill() const { return standstill_; }
  double noise() const { return noise_; }  // median per-pixel noise, grey levels

  // Masks (CV_8UC1 0/255, size of `rect`) of the pixels of `bgr`'s part `rect` that differ from
  // the empty room (`person`) and from the standstill (`moved`), the light matched. `ignore`
  // (CV_8UC1 of the whole image, may be empty) marks pixels left out of the light's estimate.
  void Compare(const cv::Mat& bgr, const cv::Rect& rect, const cv::Mat& ignore, cv::Mat* person,
               cv::Mat* moved);
  // A third reference, `bgr` (CV_8UC3, the images' size; e.g. the arm-length image), taken into
  // the standstill's light by one gain per channel.
  void SetThird(const cv::Mat& bgr);
  // After Compare on the same frame: the pixels of `bgr`'s part `rect` that differ from the third
  // reference in this frame's light (CV_8UC1 0/255, size of `rect`).
  void CompareThird(const cv::Mat& bgr, const cv::Rect& rect, cv::Mat* differs);
  // The person of the standstill: pixels of the standstill that differ from the empty room (the
  // room in shadow left out).
  void StandstillPerson(cv::Mat* mask) const;
  // Pixels of `bgr` (a whole image, e.g. the arm-length image) that differ from `reference`
  // (background() or standstill()), one gain per channel removed; the room in shadow left out.
  void Differ(const cv::Mat& bgr, const cv::Mat& reference, cv::Mat* mask) const;

 private:
  // The gain of `bgr` over the standstill, per block and channel, into gain_ (CV_32FC3 of the
  // block grid).
  void MeasureGain(const cv::Mat& bgr, const cv::Mat& ignore);

  cv::Mat sum_, sum_sq_;  // CV_32FC3 accumulators of the standstill
  int count_ = 0;
  cv::Mat background_, standstill_;      // CV_8UC3
  cv::Mat background_f_, standstill_f_;  // CV_32FC3; the background in the standstill's light
  cv::Mat third_f_;                      // CV_32FC3: SetThird's image in the standstill's light
  cv::Mat threshold_;                    // CV_8UC3: the per-pixel threshold, one copy per channel
  cv::Scalar standstill_gain_;           // of the standstill over the empty room
  double noise_ = 0;
  cv::Size blocks_;                         // the gain grid
  cv::Mat gain_, gain_map_;                 // CV_32FC3: per block; interpolated over the image
  cv::Mat scaled_f_, scaled_, diff_, any_;  // per-frame work
};

}  // namespace armmimic::bgsub
