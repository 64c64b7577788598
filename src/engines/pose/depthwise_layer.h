// A depthwise convolution layer for cv::dnn, registered as kDepthwiseLayerType: each channel
// convolved with its own kh x kw kernel (TensorFlow's SAME or VALID padding, any stride, no
// dilation), then its bias and an optional Relu or Relu6, in one pass over the channel's plane.
// OpenCV's own grouped convolution pays a fixed cost per channel that dominates on small planes
// with many channels (MoveNet's 12x12 blocks with 384 and 576 channels took about 40 % of an
// inference); this layer adds each kernel tap to whole output rows instead (docs/pose.md, "Speed
// and memory"). Channels are split over cv::parallel_for_, so one thread runs them in turn.
#pragma once

namespace armmimic::internal {

inline constexpr const char* kDepthwiseLayerType = "ArmmimicDepthwise";

// Registers kDepthwiseLayerType with cv::dnn's layer factory, once per process (thread-safe).
// Parameters: kernel_h, kernel_w, stride_h, stride_w, pad_mode ("SAME" or "VALID"), activation
// ("", "Relu" or "Relu6"); blobs: the kernel (C x 1 x kh x kw) and optionally the bias (C values).
void RegisterDepthwiseLayer();

}  // namespace armmimic::internal
