// SessionFile: a session saved as JSON (QJsonDocument), so that a video, its analysis options,
// the calibration clicks and the results survive a restart. Paths inside the session file's
// folder are stored relative to it, so the folder can move as a whole. Results are the angle
// file v1 text itself, so the session needs no other file. See docs/user-guide.md, "Sessions".
#pragma once

#include <QString>
#include <QStringList>

#include "armmimic/engines/analysis.h"

namespace armmimic::gui {

inline constexpr const char* kSessionSuffix = "armmimic";  // "scene.armmimic"

struct Session {
  QStringList inputs;       // the video, image folder or images
  AnalysisOptions options;  // everything but the inputs
  QString angle_text;       // the results as an angle file v1 ("" when there are none)
  // With both arms analysed (the pose engine's side both): the right arm's angle file, and
  // angle_text the left's ("" for one arm).
  QString right_angle_text;
  int frame = 0;  // the frame shown
  // Read only: one line naming the recorded settings this version removed, which were ignored
  // ("" when none).
  QString ignored;
};

// Writes `session` to `path` atomically. Returns "" or what went wrong, naming the file.
QString WriteSession(const QString& path, const Session& session);
// Reads a session. The message names the file, and the entry when one is wrong.
QString ReadSession(const QString& path, Session* session);

// What a dropped or opened file is, from its name (and, for .json, its first bytes).
enum class FileKind { kMedia, kAngleFile, kValProgram, kSession };
FileKind ClassifyFile(const QString& path);

}  // namespace armmimic::gui
