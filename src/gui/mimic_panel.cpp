// The Mimic panel: live camera or video to the robot, its settings summary, start and stop.
// Length: the constructor builds and wires the panel's form in one list, in the order it is shown.
#include "mimic_panel.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QShortcut>
#include <QVBoxLayout>

#include "mimic_controller.h"
#include "robot_link.h"
#include "robot_preview.h"
#include "video_view.h"

namespace armmimic::gui {
namespace {

// "J1 [-160, 160] 45°/s" for each joint, and the mapping, as the operator confirms them.
QString DescribeSettings(const robot::PlannerOptions& o) {
  QString s = QObject::tr("Mapping: %1\nLimits:").arg(QString::fromStdString(o.mapping.Describe()));
  for (int j = 0; j < robot::kJoints; ++j) {
    s += QString("  J%1 [%2, %3] %4°/s")
             .arg(j + 1)
             .arg(o.limits.min_deg[j])
             .arg(o.limits.max_deg[j])
             .arg(o.limits.max_speed_deg_s[j]);
  }
  s += QObject::tr("\nFilter %1 Hz (lags %2 ms), deadband %3°, at most one move every %4 s%5")
           .arg(o.cutoff_hz)
           .arg(o.cutoff_hz > 0 ? 1000 * 1.41421356 / (2 * 3.14159265 * o.cutoff_hz) : 0.0, 0, 'f',
                0)
           .arg(o.deadband_deg)
           .arg(o.min_interval_s)
           .arg(o.clamp ? QObject::tr(", targets clamped to the limits")
                        : QObject::tr(", targets outside the limits hold the robot"));
  return s;
}

}  // namespace

MimicPanel::MimicPanel(QWidget* parent)
    : QWidget(parent),
      controller_(new MimicController(this)),
      view_(new VideoView),
      preview_(new RobotPreview) {
  setObjectName("mimicPanel");
  // A read-only text box, not a word-wrapped label: a height-for-width label would make the
  // scrolling dock size the whole panel by the video view's preferred height.
  settings_ = new QPlainTextEdit;
  settings_->setObjectName("mimicSettings");
  settings_->setReadOnly(true);
  settings_->setFixedHeight(settings_->fontMetrics().lineSpacing() * 5 + 10);
  confirm_ = new QCheckBox(tr("I have checked this mapping and these limits for this robot"));
  confirm_->setObjectName("mimicConfirm");
  deadman_ = new QCheckBox(tr("Dead-man: move only while “Hold to move” is held"));
  deadman_->setObjectName("mimicDeadman");
  start_ = new QPushButton(tr("Start mimicking"));
  start_->setObjectName("mimicStart");
  stop_ = new QPushButton(tr("STOP   (F12 / Ctrl+.)"));
  stop_->setObjectName("mimicStop");
  stop_->setMinimumHeight(56);
  stop_->setStyleSheet(
      "QPushButton { background: #c62828; color: white; font-size: 20px; font-weight: bold; }"
      "QPushButton:disabled { background: #e6b0ae; }");
  hold_ = new QPushButton(tr("Hold to move"));
  hold_->setObjectName("mimicHold");
  hold_->setMinimumHeight(40);
  state_ = new QLabel(tr("Stopped"));
  state_->setObjectName("mimicState");
  latency_ = new QLabel(tr("Latency: no run yet"));
  latency_->setObjectName("mimicLatency");
  latency_->setMinimumWidth(1);  // a long line is cut, never widens the panel
  state_->setMinimumWidth(1);

  // Stop on top, where it is always in sight; the settings to confirm next to their tick.
  view_->setMinimumSize(200, 150);
  auto* views = new QHBoxLayout;
  views->addWidget(view_, 3);
  views->addWidget(preview_, 2);
  auto* controls = new QHBoxLayout;
  controls->addWidget(start_, 1);
  controls->addWidget(hold_, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(stop_);
  layout->addLayout(views, 1);
  layout->addWidget(state_);
  layout->addWidget(latency_);
  layout->addWidget(settings_);
  layout->addWidget(confirm_);
  layout->addWidget(deadman_);
  layout->addLayout(controls);

  // Stop works from anywhere in the application, whatever has the focus.
  stop_shortcut_ = new QShortcut(this);
  stop_shortcut_->setKeys({QKeySequence(Qt::Key_F12), QKeySequence(Qt::CTRL | Qt::Key_Period)});
  stop_shortcut_->setContext(Qt::ApplicationShortcut);
  stop_shortcut_->setObjectName("mimicStopShortcut");
  connect(stop_shortcut_, &QShortcut::activated, this, &MimicPanel::stopMimicking);
  connect(stop_, &QPushButton::clicked, this, &MimicPanel::stopMimicking);
  connect(start_, &QPushButton::clicked, this, [this] { startMimicking(); });
  connect(confirm_, &QCheckBox::toggled, this, [this](bool on) {
    controller_->setConfirmed(on);
    updateState();
  });
  connect(deadman_, &QCheckBox::toggled, this, [this](bool on) {
    controller_->setDeadman(on);
    if (on) hold_->setFocus();
    updateState();
  });
  connect(hold_, &QPushButton::pressed, this, [this] {
    controller_->setPressed(true);
    updateState();
  });
  connect(hold_, &QPushButton::released, this, [this] {
    controller_->setPressed(false);
    updateState();
  });
  connect(controller_, &MimicController::frameReady, this,
          [this](const QImage& image, int index, const ArmMeasurement& m) {
            view_->setFrame(image, index, -1);
            view_->setMeasurement(m);
          });
  connect(controller_, &MimicController::planned, this,
          [this](bool has_target, const robot::JointArray& target, const QString& hold) {
            if (has_target) {
              preview_->setPose(target, hold.isEmpty() ? tr("planned: following")
                                                       : tr("planned: holding (%1)").arg(hold));
            }
            state_->setText(hold.isEmpty() ? tr("Following") : tr("Holding: %1").arg(hold));
          });
  connect(controller_, &MimicController::latencyChanged, this,
          [this](const QString& text) { latency_->setText(tr("Latency: %1").arg(text)); });
  connect(controller_, &MimicController::runningChanged, this, [this] { updateState(); });
  connect(controller_, &MimicController::error, this, &MimicPanel::errorOccurred);
  connect(controller_, &MimicController::finished, this, [this](bool ok, const QString& text) {
    const QString where = tr("angles, journal and latency log: %1").arg(controller_->anglesPath());
    if (ok || text.startsWith("stopped by the operator")) {
      emit message(tr("Mimic live ended%1; %2").arg(text.isEmpty() ? "" : ": " + text, where));
    } else {
      emit errorOccurred(tr("Mimic live stopped: %1; %2").arg(text, where));
    }
    state_->setText(ok ? tr("Ended") : tr("Stopped: %1").arg(text));
    updateState();
  });
  refresh_.setInterval(300);
  connect(&refresh_, &QTimer::timeout, this, &MimicPanel::refreshSettings);
  refresh_.start();
  updateState();
}

MimicPanel::~MimicPanel() { controller_->stop(tr("the window closed")); }

void MimicPanel::setSources(std::function<AnalysisOptions()> analysis,
                            std::function<robot::PlannerOptions()> planner, RobotLink* link) {
  analysis_ = std::move(analysis);
  planner_ = std::move(planner);
  link_ = link;
  refreshSettings();
}

void MimicPanel::refreshSettings() {
  if (!planner_) return;
  const QString now = DescribeSettings(planner_());
  if (now == shown_) return;
  const bool was_confirmed = confirm_->isChecked();
  shown_ = now;
  settings_->setPlainText(now);
  preview_->setLimits(planner_().limits);
  if (was_confirmed) {
    confirm_->setChecked(false);  // a change the operator has not seen is not confirmed
    emit message(tr("Mimic live: the mapping or limits changed; confirm them again"));
  }
}

bool MimicPanel::startMimicking() {
  refreshSettings();
  if (!analysis_ || !planner_ || !link_) return false;
  if (link_->isSending()) {
    emit errorOccurred(tr("Mimic live: a program is being sent; wait for it or abort it"));
    return false;
  }
  const bool ok =
      controller_->start(analysis_(), planner_(), profile_source_ ? profile_source_() : profile_,
                         link_->serialLink(), link_->device());
  if (ok) {
    emit message(tr("Mimic live started on %1").arg(link_->device()));
    if (deadman_->isChecked()) hold_->setFocus();
  }
  updateState();
  return ok;
}

void MimicPanel::stopMimicking() {
  if (!controller_->running()) return;
  controller_->stop(tr("stopped by the operator"));
  state_->setText(tr("Stopping: waiting for the move in flight"));
}

void MimicPanel::updateState() {
  const bool running = controller_->running();
  start_->setEnabled(!running && confirm_->isChecked());
  stop_->setEnabled(running);
  hold_->setEnabled(deadman_->isChecked());
  confirm_->setEnabled(true);
  if (running && deadman_->isChecked() && !hold_->isDown()) {
    state_->setText(tr("Holding: dead-man released"));
  }
}

}  // namespace armmimic::gui
