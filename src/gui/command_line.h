// The desktop application's command line: armmimic [--help] [--version] [VIDEO...]. Parsed
// before any window exists (with a QCoreApplication), so --help and --version work without a
// display; Qt's own GUI options (-platform, -style, ...) are accepted and left to QApplication.
#pragma once

#include <QStringList>

namespace armmimic::gui {

struct CommandLine {
  QStringList inputs;  // a video, image files or a folder of images, to open at start
  int exit_code = -1;  // 0 or more: exit now with this code (after --help, --version or an error)
};

// Parses `arguments` (arguments()[0] is the program). --help and --version print to stdout
// (exit 0); an unknown option prints the error and a hint to stderr (exit 2, a usage error).
CommandLine ParseCommandLine(const QStringList& arguments);

}  // namespace armmimic::gui
