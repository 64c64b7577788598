// The parts of the armmimic-cvio module, gathered into its Api in cvio_module.cpp.
#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/core/video_source.h"
#include "armmimic/core/video_writer.h"

namespace armmimic::cvio {

// camera_source.cpp
std::unique_ptr<VideoSource> OpenCamera(const std::string& spec, Status* status);

// video_file_writer.cpp
std::unique_ptr<VideoFileWriter> OpenWriter(const std::string& path, const std::string& fourcc,
                                            double fps, cv::Size size, int jpeg_quality,
                                            Status* status);

}  // namespace armmimic::cvio
