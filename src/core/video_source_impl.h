// The three VideoSource implementations, created by VideoSource::Open after it has checked
// the inputs exist and has decided their kind. Private to src/core.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "armmimic/core/video_source.h"

namespace armmimic::internal {

// `path` is an existing, readable, non-empty file with a video extension.
std::unique_ptr<VideoSource> OpenVideoFileSource(const std::string& path, Status* status);
// `files` are existing image files (in the order to read them); `shown_path` goes to info().path.
std::unique_ptr<VideoSource> OpenImageSource(const std::vector<std::string>& files,
                                             const std::string& shown_path, Status* status);
// "camera:N" or a stream URL.
std::unique_ptr<VideoSource> OpenCameraSource(const std::string& spec, Status* status);

}  // namespace armmimic::internal
