#include "csv_export_dialog.h"

#include <QFileDialog>
#include <QLocale>
#include <QPushButton>

#include "ui_csv_export_dialog.h"

namespace armmimic::gui {

CsvExportDialog::CsvExportDialog(QWidget* parent, const QString& suggested_path,
                                 const QString& range, bool visible_only)
    : QDialog(parent), ui_(std::make_unique<Ui::CsvExportDialogForm>()) {
  ui_->setupUi(this);
  ui_->path->setText(suggested_path);
  // A spreadsheet in a comma-decimal language reads "1,5;2,25", not "1.5,2.25".
  setStyle(QLocale().decimalPoint() == QLatin1String(",") ? CsvStyle::kSemicolon
                                                          : CsvStyle::kComma);
  ui_->visibleRows->setEnabled(!range.isEmpty());
  if (!range.isEmpty())
    ui_->visibleRows->setText(tr("The frames in the plot's view (%1)").arg(range));
  ui_->visibleRows->setChecked(visible_only && !range.isEmpty());
  ui_->allRows->setChecked(!ui_->visibleRows->isChecked());
  connect(ui_->browse, &QToolButton::clicked, this, [this] {
    const QString p = QFileDialog::getSaveFileName(this, tr("Export CSV"), path(),
                                                   tr("CSV files (*.csv);;All files (*)"));
    if (!p.isEmpty()) setPath(p);
  });
  auto update = [this] {
    ui_->buttons->button(QDialogButtonBox::Save)->setEnabled(!path().trimmed().isEmpty());
  };
  connect(ui_->path, &QLineEdit::textChanged, this, update);
  update();
}

CsvExportDialog::~CsvExportDialog() = default;

QString CsvExportDialog::path() const { return ui_->path->text().trimmed(); }

CsvStyle CsvExportDialog::style() const {
  return ui_->semicolonStyle->isChecked() ? CsvStyle::kSemicolon : CsvStyle::kComma;
}

bool CsvExportDialog::visibleOnly() const { return ui_->visibleRows->isChecked(); }

void CsvExportDialog::setPath(const QString& path) { ui_->path->setText(path); }

void CsvExportDialog::setStyle(CsvStyle style) {
  ui_->semicolonStyle->setChecked(style == CsvStyle::kSemicolon);
  ui_->commaStyle->setChecked(style == CsvStyle::kComma);
}

}  // namespace armmimic::gui
