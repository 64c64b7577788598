#include "command_line.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <cstdio>

namespace armmimic::gui {
namespace {

// QGuiApplication's and QApplication's own options: valid on the command line, hidden from
// --help, and removed from the arguments by QApplication itself.
void AddQtOptions(QCommandLineParser& parser) {
  for (const char* name : {"platform", "platformpluginpath", "platformtheme", "plugin",
                           "qwindowgeometry", "qwindowtitle", "qwindowicon", "display", "geometry",
                           "title", "style", "stylesheet", "session", "name", "qmljsdebugger"}) {
    QCommandLineOption o(QString::fromLatin1(name), QString(), QStringLiteral("value"));
    o.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(o);
  }
  for (const char* name : {"reverse", "nograb", "dograb", "sync", "widgetcount"}) {
    QCommandLineOption o(QString::fromLatin1(name));
    o.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(o);
  }
}

void Print(std::FILE* out, const QString& text) {
  const QByteArray bytes = text.toLocal8Bit();
  std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), out);
  std::fflush(out);
}

}  // namespace

CommandLine ParseCommandLine(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QCoreApplication::translate(
      "armmimic",
      "Make a robot arm mimic a human arm seen on video: open a video, analyse it with an\n"
      "engine, check the angles and send them to the PUMA controller or its emulator.\n"
      "The command-line twin is armmimic-cli."));
  parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
  // Not addHelpOption(): its --help-all would have to print Qt's options, which QApplication
  // handles before this parser sees them.
  const QCommandLineOption help(
      {QStringLiteral("h"), QStringLiteral("help")},
      QCoreApplication::translate("armmimic", "Displays this help and exits."));
  parser.addOption(help);
  const QCommandLineOption version = parser.addVersionOption();
  AddQtOptions(parser);
  parser.addPositionalArgument(
      QStringLiteral("VIDEO"),
      QCoreApplication::translate("armmimic", "a video, image files or a folder of images to open"),
      QStringLiteral("[VIDEO...]"));
  CommandLine result;
  if (!parser.parse(arguments)) {
    Print(stderr, QStringLiteral("armmimic: %1\nTry 'armmimic --help'.\n").arg(parser.errorText()));
    result.exit_code = 2;
    return result;
  }
  if (parser.isSet(help)) {
    Print(stdout, parser.helpText());
    result.exit_code = 0;
  } else if (parser.isSet(version)) {
    Print(stdout, QStringLiteral("%1 %2\n").arg(QCoreApplication::applicationName(),
                                                QCoreApplication::applicationVersion()));
    result.exit_code = 0;
  }
  result.inputs = parser.positionalArguments();
  return result;
}

}  // namespace armmimic::gui
