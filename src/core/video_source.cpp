// VideoSource::Open: decides what the inputs are (video file, images, folder, camera/stream),
// checks them up front and hands over to one of the three sources.
#include "armmimic/core/video_source.h"

#include "armmimic/core/output_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include "armmimic/core/image_io.h"
#include "armmimic/core/text.h"
#include "video_source_impl.h"

namespace armmimic {
namespace {

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string Extension(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? "" : Lower(name.substr(dot));
}

bool IsVideoExtension(const std::string& ext) {
  static const char* const kExts[] = {".avi", ".mp4",  ".m4v",  ".mov",   ".mkv", ".webm",
                                      ".mpg", ".mpeg", ".wmv",  ".flv",   ".ogv", ".3gp",
                                      ".ts",  ".mts",  ".mjpg", ".mjpeg", ".gif", ".dv"};
  return std::any_of(std::begin(kExts), std::end(kExts), [&](const char* e) { return ext == e; });
}

// Checks that `path` is a readable, non-empty regular file.
Status CheckReadableFile(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    return Status::Error(path + ": " + (errno == ENOENT ? "no such file" : FileErrorText(errno)));
  }
  if (S_ISDIR(st.st_mode)) return Status::Error(path + ": is a folder");
  if (!S_ISREG(st.st_mode)) return Status::Error(path + ": not a regular file");
  if (access(path.c_str(), R_OK) != 0) {
    return Status::Error(path + ": cannot read (" + ErrnoText(errno) + ")");
  }
  if (st.st_size == 0) return Status::Error(path + ": empty file (0 bytes)");
  return Status::Ok();
}

Status ListFolderImages(const std::string& dir, std::vector<std::string>* files) {
  std::error_code ec;
  std::filesystem::directory_iterator it(dir, ec);
  if (ec) return Status::Error(dir + ": cannot list folder (" + ec.message() + ")");
  std::vector<std::pair<std::string, std::string>> found;  // (file name, full path)
  for (const auto& entry : it) {
    std::error_code fec;
    if (!entry.is_regular_file(fec)) continue;
    const std::string name = entry.path().filename().string();
    if (!name.empty() && name[0] == '.') continue;  // hidden and temporary files
    if (HasImageExtension(name)) found.emplace_back(name, entry.path().string());
  }
  if (found.empty()) {
    return Status::Error(dir +
                         ": no images in folder (looked for png, jpg, jpeg, bmp, tif, tiff, pgm, "
                         "ppm)");
  }
  std::sort(found.begin(), found.end());
  files->clear();
  for (auto& f : found) files->push_back(std::move(f.second));
  return Status::Ok();
}

}  // namespace

std::unique_ptr<VideoSource> VideoSource::Open(const std::vector<std::string>& inputs,
                                               Status* status) {
  Status local;
  Status& st = status ? *status : local;
  st = Status::Ok();
  if (inputs.empty()) {
    st = Status::Error("no input given (a video, a folder of images, image files or camera:N)");
    return nullptr;
  }
  for (const std::string& in : inputs) {
    if (in.empty()) {
      st = Status::Error("an input path is empty");
      return nullptr;
    }
  }
  const std::string& first = inputs.front();
  if (inputs.size() == 1 &&
      (StartsWith(first, "camera:") || StartsWith(Lower(first), "rtsp://") ||
       StartsWith(Lower(first), "http://") || StartsWith(Lower(first), "https://"))) {
    return internal::OpenCameraSource(first, &st);
  }

  if (inputs.size() == 1) {
    struct stat sb {};
    if (stat(first.c_str(), &sb) == 0 && S_ISDIR(sb.st_mode)) {
      std::vector<std::string> files;
      st = ListFolderImages(first, &files);
      if (!st) return nullptr;
      return internal::OpenImageSource(files, first, &st);
    }
    st = CheckReadableFile(first);
    if (!st) return nullptr;
    if (HasImageExtension(first)) return internal::OpenImageSource(inputs, first, &st);
    const std::string ext = Extension(first);
    if (!IsVideoExtension(ext)) {
      st = Status::Error(first + ": unsupported file type " +
                         (ext.empty() ? std::string("(no extension)") : "'" + ext + "'") +
                         "; expected a video (avi, mp4, mov, mkv, ...) or an image (png, jpg, "
                         "jpeg, bmp, tif, tiff, pgm, ppm)");
      return nullptr;
    }
    return internal::OpenVideoFileSource(first, &st);
  }

  // Several inputs: image files, in the given order.
  for (const std::string& in : inputs) {
    st = CheckReadableFile(in);
    if (!st) return nullptr;
    if (!HasImageExtension(in)) {
      st = Status::Error(in +
                         ": several inputs must all be image files (png, jpg, jpeg, bmp, tif, "
                         "tiff, pgm, ppm); give a video on its own");
      return nullptr;
    }
  }
  return internal::OpenImageSource(inputs, first, &st);
}

}  // namespace armmimic
