#include "angle_panel.h"

#include <QAction>
#include <QFileDialog>

#include "angle_plot.h"
#include "recent_files.h"
#include "ui_angle_panel.h"

namespace armmimic::gui {

AnglePanel::AnglePanel(QWidget* parent)
    : QWidget(parent), ui_(std::make_unique<Ui::AnglePanelForm>()) {
  ui_->setupUi(this);
  plot_ = ui_->anglePlot;
  auto* reset = new QAction(tr("Reset zoom"), this);
  auto* seconds = new QAction(tr("Seconds"), this);
  seconds->setToolTip(tr("Time in seconds on the axis instead of frame numbers"));
  seconds->setCheckable(true);
  auto* image = new QAction(tr("Save image…"), this);
  auto* range = new QAction(tr("Save range as CSV…"), this);
  ui_->resetZoomButton->setDefaultAction(reset);
  ui_->secondsButton->setDefaultAction(seconds);
  ui_->exportImageButton->setDefaultAction(image);
  ui_->exportRangeButton->setDefaultAction(range);
  plot_->addActions({reset, seconds, image, range});  // the right-click menu
  connect(reset, &QAction::triggered, plot_, &AnglePlot::resetZoom);
  connect(seconds, &QAction::toggled, plot_, &AnglePlot::setTimeAxis);
  connect(image, &QAction::triggered, this, [this] {
    const QString suggested =
        suggested_path_.isEmpty() ? RecentFiles::lastDir() + "/angles-plot.png" : suggested_path_;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the plot"), suggested,
                                                      tr("PNG image (*.png);;SVG drawing (*.svg)"));
    if (!path.isEmpty()) saveImage(path);
  });
  connect(range, &QAction::triggered, this, &AnglePanel::rangeCsvRequested);
  connect(plot_, &AnglePlot::hovered, ui_->plotReadout, &QLabel::setText);
  connect(plot_, &AnglePlot::zoomChanged, reset,
          [this, reset] { reset->setEnabled(plot_->isZoomed()); });
  reset->setEnabled(false);
  updateTimeAxisButton();
  ui_->armPick->hide();
  connect(ui_->armPick, &QComboBox::currentIndexChanged, this, &AnglePanel::armChanged);
}

void AnglePanel::setArmCount(int arms) { ui_->armPick->setVisible(arms > 1); }

int AnglePanel::arm() const { return ui_->armPick->isHidden() ? 0 : ui_->armPick->currentIndex(); }

void AnglePanel::setArm(int arm) { ui_->armPick->setCurrentIndex(arm); }

AnglePanel::~AnglePanel() = default;

QString AnglePanel::readout() const { return ui_->plotReadout->text(); }

bool AnglePanel::saveImage(const QString& path) {
  const QString error = plot_->saveImage(path);
  if (!error.isEmpty()) {
    emit errorOccurred(error);
    return false;
  }
  RecentFiles::rememberDir(path);
  emit message(tr("Saved the plot to %1").arg(path));
  return true;
}

void AnglePanel::updateTimeAxisButton() {
  QAction* seconds = ui_->secondsButton->defaultAction();
  seconds->setEnabled(plot_->canShowTime());
  const QSignalBlocker block(seconds);
  seconds->setChecked(plot_->timeAxis());
}

}  // namespace armmimic::gui
