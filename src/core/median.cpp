// Median filter (thesis Fig. 3-8). The 3x3 and 5x5 windows use exchange networks on 16 pixels
// at a time; larger windows use Huang's running histogram, where each output pixel costs one
// column out and one column in.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic {
namespace {

inline void Exchange(uint8_t& a, uint8_t& b) {
  const uint8_t lo = std::min(a, b);
  b = std::max(a, b);
  a = lo;
}

#if CV_SIMD128
inline void Exchange(cv::v_uint8x16& a, cv::v_uint8x16& b) {
  const cv::v_uint8x16 lo = cv::v_min(a, b);
  b = cv::v_max(a, b);
  a = lo;
}
#endif

// Median of nine by the classic 19-exchange network; p[4] ends as the median.
template <typename T>
inline T Median9(T* p) {
  Exchange(p[1], p[2]);
  Exchange(p[4], p[5]);
  Exchange(p[7], p[8]);
  Exchange(p[0], p[1]);
  Exchange(p[3], p[4]);
  Exchange(p[6], p[7]);
  Exchange(p[1], p[2]);
  Exchange(p[4], p[5]);
  Exchange(p[7], p[8]);
  Exchange(p[0], p[3]);
  Exchange(p[5], p[8]);
  Exchange(p[4], p[7]);
  Exchange(p[3], p[6]);
  Exchange(p[1], p[4]);
  Exchange(p[2], p[5]);
  Exchange(p[4], p[7]);
  Exchange(p[4], p[2]);
  Exchange(p[6], p[4]);
  Exchange(p[4], p[2]);
  return p[4];
}

// Sorts five values by a 9-exchange network.
template <typename T>
inline void Sort5(T& a, T& b, T& c, T& d, T& e) {
  Exchange(a, b);
  Exchange(d, e);
  Exchange(c, e);
  Exchange(c, d);
  Exchange(a, d);
  Exchange(a, c);
  Exchange(b, e);
  Exchange(b, d);
  Exchange(b, c);
}

// Median of the 13 values p[0..13) by forgetful selection: of 8 candidates (13 / 2 + 2) neither
// extreme can be the median, so both go and the next value comes in, until one is left.
template <int Lo, int Hi, int Next, typename T>
inline T Forgetful13(T* p) {
  for (int i = Lo + 1; i < Hi; ++i) Exchange(p[Lo], p[i]);
  for (int i = Lo + 1; i < Hi - 1; ++i) Exchange(p[i], p[Hi - 1]);
  if constexpr (Next == 13) {
    static_assert(Hi - Lo == 3, "one candidate must remain");
    return p[Lo + 1];
  } else {
    p[Hi - 1] = p[Next];
    return Forgetful13<Lo + 1, Hi, Next + 1>(p);
  }
}

// 5x5 median: the window's columns are sorted once per row (shared by five windows), then
// each window sorts its five rank rows. The result is sorted along both axes, so 6 values are
// surely below the median and 6 surely above; the median is that of the 13 others.
template <typename T>
inline T Median25FromSortedColumns(T s[5][5]) {  // s[rank][column]
  for (int r = 0; r < 5; ++r) Sort5(s[r][0], s[r][1], s[r][2], s[r][3], s[r][4]);
  T c[13] = {s[0][3], s[0][4], s[1][2], s[1][3], s[1][4], s[2][1], s[2][2],
             s[2][3], s[3][0], s[3][1], s[3][2], s[4][0], s[4][1]};
  return Forgetful13<0, 8, 8>(c);
}

void Median5x5(const cv::Mat& padded, cv::Mat* out, std::vector<uint8_t>* buffer) {
  const int w = out->cols;
  const int pw = padded.cols;  // w + 4
  buffer->resize(static_cast<size_t>(5) * pw);
  uint8_t* sorted[5];
  for (int r = 0; r < 5; ++r) sorted[r] = buffer->data() + static_cast<size_t>(r) * pw;
  for (int y = 0; y < out->rows; ++y) {
    const uint8_t* rows[5];
    for (int i = 0; i < 5; ++i) rows[i] = padded.ptr<uint8_t>(y + i);
    int cx = 0;
#if CV_SIMD128
    for (; cx + 16 <= pw; cx += 16) {
      cv::v_uint8x16 a = cv::v_load(rows[0] + cx), b = cv::v_load(rows[1] + cx),
                     c = cv::v_load(rows[2] + cx), d = cv::v_load(rows[3] + cx),
                     e = cv::v_load(rows[4] + cx);
      Sort5(a, b, c, d, e);
      cv::v_store(sorted[0] + cx, a);
      cv::v_store(sorted[1] + cx, b);
      cv::v_store(sorted[2] + cx, c);
      cv::v_store(sorted[3] + cx, d);
      cv::v_store(sorted[4] + cx, e);
    }
#endif
    for (; cx < pw; ++cx) {
      uint8_t a = rows[0][cx], b = rows[1][cx], c = rows[2][cx], d = rows[3][cx], e = rows[4][cx];
      Sort5(a, b, c, d, e);
      sorted[0][cx] = a;
      sorted[1][cx] = b;
      sorted[2][cx] = c;
      sorted[3][cx] = d;
      sorted[4][cx] = e;
    }
    uint8_t* dst = out->ptr<uint8_t>(y);
    int x = 0;
#if CV_SIMD128
    for (; x + 16 <= w; x += 16) {
      cv::v_uint8x16 s[5][5];
      for (int r = 0; r < 5; ++r) {
        for (int j = 0; j < 5; ++j) s[r][j] = cv::v_load(sorted[r] + x + j);
      }
      cv::v_store(dst + x, Median25FromSortedColumns(s));
    }
#endif
    for (; x < w; ++x) {
      uint8_t s[5][5];
      for (int r = 0; r < 5; ++r) {
        for (int j = 0; j < 5; ++j) s[r][j] = sorted[r][x + j];
      }
      dst[x] = Median25FromSortedColumns(s);
    }
  }
}

void Median3x3(const cv::Mat& padded, cv::Mat* out) {
  const int w = out->cols;
  for (int y = 0; y < out->rows; ++y) {
    const uint8_t* r0 = padded.ptr<uint8_t>(y);
    const uint8_t* r1 = padded.ptr<uint8_t>(y + 1);
    const uint8_t* r2 = padded.ptr<uint8_t>(y + 2);
    uint8_t* dst = out->ptr<uint8_t>(y);
    int x = 0;
#if CV_SIMD128
    for (; x + 16 <= w; x += 16) {
      cv::v_uint8x16 p[9] = {cv::v_load(r0 + x), cv::v_load(r0 + x + 1), cv::v_load(r0 + x + 2),
                             cv::v_load(r1 + x), cv::v_load(r1 + x + 1), cv::v_load(r1 + x + 2),
                             cv::v_load(r2 + x), cv::v_load(r2 + x + 1), cv::v_load(r2 + x + 2)};
      cv::v_store(dst + x, Median9(p));
    }
#endif
    for (; x < w; ++x) {
      uint8_t p[9] = {r0[x],     r0[x + 1], r0[x + 2], r1[x],    r1[x + 1],
                      r1[x + 2], r2[x],     r2[x + 1], r2[x + 2]};
      dst[x] = Median9(p);
    }
  }
}

}  // namespace

void MedianFilter(const cv::Mat& gray, int ksize, cv::Mat* out) {
  if (ksize <= 0 || ksize % 2 == 0) {
    throw std::invalid_argument("MedianFilter: window size must be odd and positive, got " +
                                std::to_string(ksize));
  }
  if (gray.type() != CV_8UC1) throw std::invalid_argument("MedianFilter: image must be CV_8UC1");
  if (out == &gray) throw std::invalid_argument("MedianFilter: output must not be the input");
  const int r = ksize / 2;
  cv::Mat padded;
  // ISOLATED: a ROI of a larger image replicates its own edge, like a standalone image.
  cv::copyMakeBorder(gray, padded, r, r, r, r, cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);
  out->create(gray.size(), CV_8UC1);
  if (ksize == 1) {
    gray.copyTo(*out);
    return;
  }
  if (ksize == 3) {
    Median3x3(padded, out);
    return;
  }
  if (ksize == 5) {
    std::vector<uint8_t> buffer;
    Median5x5(padded, out, &buffer);
    return;
  }
  const int w = gray.cols;
  const int h = gray.rows;
  const int half = (ksize * ksize) / 2;  // rank of the median among ksize^2 values, 0-based
  int hist[256];
  for (int y = 0; y < h; ++y) {
    std::memset(hist, 0, sizeof(hist));
    // Window rows y..y+2r of the padded image, columns 0..2r for x = 0.
    for (int dy = 0; dy < ksize; ++dy) {
      const uint8_t* row = padded.ptr<uint8_t>(y + dy);
      for (int dx = 0; dx < ksize; ++dx) ++hist[row[dx]];
    }
    int median = 0;
    int below = 0;  // number of window values < median
    while (below + hist[median] <= half) below += hist[median++];
    uint8_t* dst = out->ptr<uint8_t>(y);
    dst[0] = static_cast<uint8_t>(median);
    for (int x = 1; x < w; ++x) {
      const int left = x - 1;       // padded column leaving the window
      const int right = x + 2 * r;  // padded column entering it
      for (int dy = 0; dy < ksize; ++dy) {
        const uint8_t* row = padded.ptr<uint8_t>(y + dy);
        const int vo = row[left];
        const int vi = row[right];
        --hist[vo];
        below -= vo < median;
        ++hist[vi];
        below += vi < median;
      }
      if (below > half) {
        do {
          --median;
          below -= hist[median];
        } while (below > half);
      } else {
        while (below + hist[median] <= half) below += hist[median++];
      }
      dst[x] = static_cast<uint8_t>(median);
    }
  }
}

cv::Mat MedianFilter(const cv::Mat& gray, int ksize) {
  cv::Mat out;
  MedianFilter(gray, ksize, &out);
  return out;
}

}  // namespace armmimic
