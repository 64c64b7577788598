// The robot panel: its construction, the arm preview (pose, animation, the simulated
// controller's joints) and the link box (ports, simulator, connect, buttons). The plan box is
// in robot_panel_plan.cpp, sending in robot_panel_send.cpp, saved settings in
// robot_panel_settings.cpp.
// Length: the constructor wires the preview, the animation, the simulator poll and the link's
// signals in one place.
#include "robot_panel.h"

#include <memory>

#include <QComboBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>

#include "arm_view_3d.h"
#include "armmimic/serial/serial_link.h"
#include "controller_settings.h"
#include "robot_link.h"
#include "robot_preview.h"
#include "sim_controller.h"
#include "ui_robot_panel.h"
#include "wheel_guard.h"

namespace armmimic::gui {

RobotPanel::RobotPanel(QWidget* parent)
    : QWidget(parent),
      ui_(std::make_unique<Ui::RobotPanelForm>()),
      link_(new RobotLink(this)),
      sim_(new SimController(this)) {
  ui_->setupUi(this);  // the static layout: ui/robot_panel.ui
  controller_ = new ControllerSettings(*ui_, this);
  connect(controller_, &ControllerSettings::errorOccurred, this, &RobotPanel::errorOccurred);
  connect(controller_, &ControllerSettings::profileChanged, this,
          [this](const robot::ControllerProfile& profile) {
            profile_ = profile;
            emit message(tr("Controller profile: %1 (%2 mode)")
                             .arg(QString::fromStdString(profile.name))
                             .arg(robot::SendModeName(profile.mode)));
          });
  preview_ = ui_->robotPreview;
  view3d_ = new ArmView3D;
  ui_->view3dLayout->addWidget(view3d_);
  animate_button_ = ui_->animateButton;
  connect(ui_->compactButton, &QPushButton::toggled, this, [this](bool on) {
    ui_->previewStack->setCurrentIndex(on ? 1 : 0);
    ui_->resetViewButton->setEnabled(!on && view3d_->drawsIn3D());
  });
  connect(ui_->resetViewButton, &QPushButton::clicked, view3d_, &ArmView3D::resetView);
  // Without OpenGL the 3-D page only says why; the compact views show the arm.
  ui_->compactButton->setChecked(!view3d_->drawsIn3D());
  ui_->resetViewButton->setEnabled(view3d_->drawsIn3D() && !ui_->compactButton->isChecked());
  wirePlanBox();
  wireLinkBox();

  animate_.setInterval(40);
  connect(&animate_, &QTimer::timeout, this, [this] {
    anim_t_ += 0.04;
    if (anim_t_ > plan_.trajectory().duration_s()) anim_t_ = 0;
    showArm(plan_.PoseAt(anim_t_), tr("plan t=%1 s").arg(anim_t_, 0, 'f', 1));
  });
  connect(animate_button_, &QPushButton::toggled, this, [this](bool on) {
    if (on) {
      anim_t_ = 0;
      animate_.start();
    } else {
      animate_.stop();
      showPose();
    }
  });
  sim_poll_.setInterval(50);
  connect(&sim_poll_, &QTimer::timeout, this, [this] {
    if (!animate_.isActive() && sim_->isRunning() && link_->isConnected()) {
      showArm(sim_->joints(), tr("simulated controller"));
    }
  });
  connect(link_, &RobotLink::connectedChanged, this, [this](bool on, const QString& dev) {
    emit linkStateChanged(on ? tr("robot: %1").arg(dev) : tr("robot: not connected"));
    emit message(on ? tr("Connected to %1").arg(dev) : tr("Disconnected from %1").arg(dev));
    if (on && sim_->isRunning()) sim_poll_.start();
    if (!on) {
      sim_poll_.stop();
      showPose();  // the 3-D view follows the link: no controller's pose once it is gone
    }
    updateButtons();
  });
  connect(link_, &RobotLink::error, this, &RobotPanel::errorOccurred);
  connect(link_, &RobotLink::note, this, &RobotPanel::message);
  connect(link_, &RobotLink::received, this,
          [this](const QString& line) { replies_->appendPlainText(line); });
  connect(link_, &RobotLink::progress, this, [this](int done, int total) {
    send_progress_->setRange(0, std::max(1, total));
    send_progress_->setValue(done);
  });
  connect(link_, &RobotLink::finished, this, [this](bool ok, const QString& msg) {
    if (ok || link_->wasAborted()) {  // an abort is the operator's own choice, not a fault
      emit message(msg);
    } else {
      emit errorOccurred(msg);
    }
    emit linkStateChanged(tr("robot: %1").arg(link_->device()));
    updateButtons();
    emit sendingChanged(false);
    emit sendFinished(ok);
  });
  const robot::JointLimits limits = plannerOptions().limits;
  preview_->setLimits(limits);
  view3d_->setLimits(limits);
  GuardWheel(this);
  updateButtons();
}

RobotPanel::~RobotPanel() {
  link_->disconnectPort();
  sim_->stop();
}

void RobotPanel::showArm(const robot::JointArray& joint_deg, const QString& caption) {
  preview_->setPose(joint_deg, caption);
  view3d_->setPose(joint_deg, caption);
}

void RobotPanel::wireLinkBox() {
  Ui::RobotPanelForm& u = *ui_;
  port_ = u.portCombo;
  sim_speed_ = u.simSpeed;
  sim_button_ = u.simButton;
  connect_button_ = u.connectButton;
  send_button_ = u.sendButton;
  pause_button_ = u.pauseButton;
  resume_button_ = u.resumeButton;
  abort_button_ = u.abortButton;
  send_progress_ = u.sendProgress;
  replies_ = u.replyLog;
  connect(u.rescanButton, &QPushButton::clicked, this, &RobotPanel::refreshPorts);
  connect(sim_button_, &QPushButton::clicked, this, [this] {
    if (sim_->isRunning()) {
      link_->disconnectPort();
      sim_->stop();
      sim_poll_.stop();
      emit message(tr("Simulated controller stopped"));
      refreshPorts();
      updateButtons();
      showPose();  // the plan again, not the stopped controller's last pose
    } else if (startSimulator(sim_speed_->value())) {
      connectTo(sim_->devicePath());  // started to be sent to: Send is ready at once
    }
  });
  connect(connect_button_, &QPushButton::clicked, this, [this] {
    if (link_->isConnected()) {
      link_->disconnectPort();
    } else {
      connectTo(port_->currentText().section(' ', 0, 0));
    }
  });
  connect(send_button_, &QPushButton::clicked, this, [this] { sendPlan(false); });
  connect(resume_button_, &QPushButton::clicked, this, [this] { resumeSend(false); });
  connect(pause_button_, &QPushButton::toggled, link_, &RobotLink::setPaused);
  connect(abort_button_, &QPushButton::clicked, link_, &RobotLink::abort);
  refreshPorts();
}

void RobotPanel::refreshPorts() {
  const QString current = port_->currentText();
  port_->clear();
  if (sim_->isRunning()) port_->addItem(sim_->devicePath() + " (simulated)");
  for (const serial::PortInfo& info : serial::ListPorts()) {
    const QString description = QString::fromStdString(info.description);
    port_->addItem(QString::fromStdString(info.system_location) +
                   (description.isEmpty() ? QString() : " (" + description + ")"));
  }
  if (!current.isEmpty() && port_->findText(current) < 0 && !sim_->isRunning()) {
    port_->setEditText(current);
  }
}

void RobotPanel::updateButtons() {
  const bool connected = link_->isConnected();
  const bool sending = link_->isSending();
  connect_button_->setText(connected ? tr("Disconnect") : tr("Connect"));
  sim_button_->setText(sim_->isRunning() ? tr("Stop simulated controller")
                                         : tr("Start simulated controller"));
  const bool sendable = connected && plan_.planned() && !sending && !angles_changing_;
  send_button_->setEnabled(sendable);
  resume_button_->setEnabled(sendable);
  pause_button_->setEnabled(sending);
  abort_button_->setEnabled(sending);
  if (!sending) {
    const QSignalBlocker block(pause_button_);
    pause_button_->setChecked(false);
  }
  port_->setEnabled(!connected);
  controller_->setPortEditable(!connected);
}

void RobotPanel::setAnglesChanging(bool changing) {
  angles_changing_ = changing;
  updateButtons();
}

void RobotPanel::setVideoFrame(int frame) {
  video_frame_ = frame;
  showPose();
}

void RobotPanel::showPose() {
  if (animate_.isActive()) return;
  if (sim_->isRunning() && link_->isConnected()) return;  // the poll shows the controller
  robot::JointArray j;
  robot::PersonArm person;
  view3d_->setPersonArm(plan_.loaded() && plan_.PersonArmAt(video_frame_, plannerOptions(), &person)
                            ? std::optional<robot::PersonArm>(person)
                            : std::nullopt);
  if (plan_.loaded() && plan_.MappedPose(video_frame_, plannerOptions(), &j)) {
    showArm(j, tr("frame %1 (mapped, unfiltered)").arg(video_frame_));
  } else if (plan_.planned()) {
    const int k = plan_.KeyframeForFrame(video_frame_);
    showArm(plan_.trajectory().keyframes[std::max(0, k)].joint_deg,
            tr("plan near frame %1").arg(video_frame_));
  } else {
    showArm(robot::JointArray{0, -90, 0, 0, 0, 0}, tr("no plan"));
  }
}

bool RobotPanel::startSimulator(double time_scale) {
  QString error;
  if (!sim_->start(time_scale, plannerOptions().limits, &error)) {
    emit errorOccurred(tr("simulated controller: %1").arg(error));
    return false;
  }
  emit message(tr("Simulated controller on %1").arg(sim_->devicePath()));
  refreshPorts();
  port_->setCurrentIndex(0);
  updateButtons();
  return true;
}

bool RobotPanel::connectTo(const QString& device) {
  if (device.isEmpty()) {
    emit errorOccurred(tr("No port chosen: pick one or start the simulated controller"));
    return false;
  }
  return link_->connectPort(controller_->portSettings(device));
}

QString RobotPanel::replyLog() const { return replies_->toPlainText(); }

}  // namespace armmimic::gui
