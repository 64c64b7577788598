#include "status_line.h"

#include <cmath>

#include <QLabel>
#include <QProgressBar>
#include <QStatusBar>

namespace armmimic::gui {

StatusLine::StatusLine(QStatusBar* bar)
    : QObject(bar),
      frame_(new QLabel),
      phase_(new QLabel),
      progress_(new QProgressBar),
      link_(new QLabel) {
  frame_->setObjectName("frameStatus");
  link_->setObjectName("linkStatus");
  progress_->setMaximumWidth(180);
  progress_->setVisible(false);
  phase_->setVisible(false);
  bar->addWidget(frame_);
  bar->addPermanentWidget(phase_);
  bar->addPermanentWidget(progress_);
  bar->addPermanentWidget(link_);
  link_->setText(tr("robot: not connected"));
}

void StatusLine::setFrameText(const QString& text) { frame_->setText(text); }
QString StatusLine::frameText() const { return frame_->text(); }

void StatusLine::showFrame(const QString& frame, double time_s, const QString& state) {
  if (std::isnan(time_s)) {  // still images: no time
    frame_->setText(QString("%1   %2").arg(frame, state));
  } else {
    frame_->setText(QString("%1   %2 s   %3").arg(frame).arg(time_s, 0, 'f', 2).arg(state));
  }
}

void StatusLine::showNoVideo() { frame_->setText(tr("No video")); }
QString StatusLine::linkText() const { return link_->text(); }

void StatusLine::setBusy(bool busy) {
  progress_->setVisible(busy);
  phase_->setVisible(busy);
  if (busy) {
    progress_->setRange(0, 0);
    phase_->clear();
  }
}

void StatusLine::setPhase(const QString& phase) { phase_->setText(phase); }

void StatusLine::setProgress(int done, int total) {
  progress_->setRange(0, total > 0 ? total : 0);
  progress_->setValue(done);
}

void StatusLine::setLinkText(const QString& text) { link_->setText(text); }

}  // namespace armmimic::gui
