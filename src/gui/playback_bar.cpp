#include "playback_bar.h"

#include <QSettings>

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QToolButton>

namespace armmimic::gui {

PlaybackBar::PlaybackBar(QWidget* parent)
    : QWidget(parent),
      buttons_(new QWidget(this)),
      slider_(new QSlider(Qt::Horizontal, this)),
      label_(new QLabel(this)),
      speed_(new QComboBox(this)) {
  auto* bl = new QHBoxLayout(buttons_);
  bl->setContentsMargins(0, 0, 0, 0);
  bl->setSpacing(0);
  slider_->setObjectName("scrubSlider");
  slider_->setRange(0, 0);
  slider_->setTracking(true);
  slider_->setFocusPolicy(Qt::NoFocus);  // arrows step frames through the window's actions
  label_->setObjectName("frameLabel");
  label_->setMinimumWidth(label_->fontMetrics().horizontalAdvance("00000 / 00000  000.00 s"));
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  for (double s : {0.25, 0.5, 1.0, 2.0, 4.0}) speed_->addItem(QString("%1×").arg(s), s);
  speed_->setCurrentIndex(2);
  speed_->setToolTip(tr("Playback speed"));
  speed_->setFocusPolicy(Qt::NoFocus);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  layout->addWidget(buttons_);
  layout->addWidget(slider_, 1);
  layout->addWidget(label_);
  layout->addWidget(speed_);
  // Programmatic moves block the slider's signals, so every change here is the user's.
  connect(slider_, &QSlider::valueChanged, this, &PlaybackBar::seekRequested);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this] { emit speedChanged(speed_->currentData().toDouble()); });
  setPosition(0, 0);
}

void PlaybackBar::addActions(const QList<QAction*>& actions) {
  for (QAction* a : actions) {
    auto* b = new QToolButton(buttons_);
    b->setDefaultAction(a);
    b->setAutoRaise(true);
    b->setFocusPolicy(Qt::NoFocus);
    buttons_->layout()->addWidget(b);
  }
}

void PlaybackBar::setFrameCount(int count, double fps) {
  count_ = count;
  fps_ = fps;
  const QSignalBlocker block(slider_);
  slider_->setRange(0, std::max(0, count - 1));
  slider_->setEnabled(count > 1);
}

void PlaybackBar::setPosition(int frame, double time_s) {
  {
    const QSignalBlocker block(slider_);
    slider_->setValue(frame);
  }
  const QString total = count_ > 0 ? QString::number(count_ - 1) : QStringLiteral("–");
  // Still images have no frame rate, so no time.
  label_->setText(fps_ > 0 || count_ <= 0
                      ? QString("%1 / %2  %3 s").arg(frame).arg(total).arg(time_s, 0, 'f', 2)
                      : QString("%1 / %2").arg(frame).arg(total));
}

int PlaybackBar::position() const { return slider_->value(); }
double PlaybackBar::speed() const { return speed_->currentData().toDouble(); }

void PlaybackBar::setSpeed(double speed) {
  const int i = speed_->findData(speed);
  if (i >= 0) speed_->setCurrentIndex(i);
}

void PlaybackBar::saveSettings(QSettings& s) const { s.setValue("playback/speed", speed()); }

void PlaybackBar::loadSettings(QSettings& s) {
  setSpeed(s.value("playback/speed", 1.0).toDouble());
}

}  // namespace armmimic::gui
