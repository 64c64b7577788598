// CsvExportDialog: where and how to write the angles as CSV: the file, the number style (comma
// and decimal point, or semicolon and decimal comma, preselected from the locale), and all rows
// or only the frames in the plot's view. The form is ui/csv_export_dialog.ui.
#pragma once

#include <memory>

#include <QDialog>

#include "armmimic/core/angle_csv.h"

namespace Ui {
class CsvExportDialogForm;
}

namespace armmimic::gui {

class CsvExportDialog : public QDialog {
  Q_OBJECT
 public:
  // `range` is what the plot shows ("frames 20–80"); "" leaves only "every frame".
  CsvExportDialog(QWidget* parent, const QString& suggested_path, const QString& range,
                  bool visible_only);
  ~CsvExportDialog() override;

  QString path() const;
  CsvStyle style() const;
  bool visibleOnly() const;
  void setPath(const QString& path);
  void setStyle(CsvStyle style);

 private:
  std::unique_ptr<Ui::CsvExportDialogForm> ui_;
};

}  // namespace armmimic::gui
