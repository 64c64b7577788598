// The static layouts come from the Qt Designer forms in ui/: every widget a form names is on
// screen, of the class the form gives it, in the window, panel or dialog built from that form.
#include <functional>
#include <map>
#include <memory>

#include <QDir>
#include <QFile>
#include <QRegularExpression>

#include "angle_panel.h"
#include "csv_export_dialog.h"
#include "gui_fixture.h"
#include "main_window.h"
#include "robot_panel.h"

namespace armmimic::test {
namespace {

class FormsTest : public GuiTest {};

TEST_F(FormsTest, EveryFormInUiIsWhatTheApplicationShows) {
  // The widget each form builds; a new form without an entry here fails the test.
  const std::map<QString, std::function<std::unique_ptr<QWidget>()>> owners = {
      {"main_window.ui", [] { return std::make_unique<gui::MainWindow>(); }},
      {"robot_panel.ui", [] { return std::make_unique<gui::RobotPanel>(); }},
      {"angle_panel.ui", [] { return std::make_unique<gui::AnglePanel>(); }},
      {"csv_export_dialog.ui",
       [] {
         return std::make_unique<gui::CsvExportDialog>(nullptr, "a.csv", "frames 1–2", false);
       }},
  };
  const QDir ui(QString::fromStdString(SourcePath("ui")));
  const QStringList forms = ui.entryList({"*.ui"}, QDir::Files, QDir::Name);
  ASSERT_GE(forms.size(), 4);
  const QRegularExpression widget(R"re(<widget class="([^"]+)" name="([^"]+)")re");
  for (const QString& form : forms) {
    SCOPED_TRACE(form.toStdString());
    ASSERT_EQ(owners.count(form), 1u) << "no test builds " << form.toStdString();
    QFile f(ui.filePath(form));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QString xml = QString::fromUtf8(f.readAll());
    const std::unique_ptr<QWidget> built = owners.at(form)();
    int checked = 0;
    for (auto it = widget.globalMatch(xml); it.hasNext();) {
      const QRegularExpressionMatch m = it.next();
      const QString cls = m.captured(1), name = m.captured(2);
      QObject* o = built->objectName() == name ? built.get() : built->findChild<QObject*>(name);
      ASSERT_NE(o, nullptr) << name.toStdString() << " (" << cls.toStdString() << ") is missing";
      EXPECT_TRUE(o->inherits(cls.toUtf8().constData()))
          << name.toStdString() << " is a " << o->metaObject()->className() << ", not "
          << cls.toStdString();
      ++checked;
    }
    EXPECT_GT(checked, 3);
  }
}

}  // namespace
}  // namespace armmimic::test
