#include "robot_panel.h"

#include <cmath>
#include <sstream>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include "armmimic/core/atomic_file.h"
#include "armmimic/robot/val_program.h"
#include "armmimic/serial/serial_link.h"
#include "recent_files.h"
#include "robot_link.h"
#include "robot_preview.h"
#include "sim_controller.h"
#include "wheel_guard.h"

namespace armmimic::gui {
namespace {

QDoubleSpinBox* DSpin(double lo, double hi, double v, int dec, const QString& tip,
                      const QString& name) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(dec);
  s->setValue(v);
  s->setToolTip(tip);
  s->setObjectName(name);
  return s;
}

}  // namespace

RobotPanel::RobotPanel(QWidget* parent)
    : QWidget(parent),
      link_(new RobotLink(this)),
      sim_(new SimController(this)),
      preview_(new RobotPreview) {
  setObjectName("robotPanel");
  auto* pv = new QWidget;
  auto* pvl = new QVBoxLayout(pv);
  pvl->setContentsMargins(0, 0, 0, 0);
  pvl->addWidget(preview_, 1);
  animate_button_ = new QPushButton(tr("Animate plan"));
  animate_button_->setObjectName("animateButton");
  animate_button_->setCheckable(true);
  pvl->addWidget(animate_button_);
  auto scrolled = [](QWidget* w) {
    auto* scroll = new QScrollArea;
    scroll->setWidget(w);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    return scroll;
  };
  auto* tabs = new QTabWidget;
  tabs->setObjectName("robotTabs");
  tabs->addTab(scrolled(makePlanBox()), tr("Plan"));
  tabs->addTab(scrolled(makeLinkBox()), tr("Controller"));
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(2, 2, 2, 2);
  outer->addWidget(pv, 2);
  outer->addWidget(tabs, 3);

  animate_.setInterval(40);
  connect(&animate_, &QTimer::timeout, this, [this] {
    anim_t_ += 0.04;
    if (anim_t_ > plan_.trajectory().duration_s()) anim_t_ = 0;
    preview_->setPose(plan_.PoseAt(anim_t_), tr("plan t=%1 s").arg(anim_t_, 0, 'f', 1));
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
      preview_->setPose(sim_->joints(), tr("simulated controller"));
    }
  });
  connect(link_, &RobotLink::connectedChanged, this, [this](bool on, const QString& dev) {
    emit linkStateChanged(on ? tr("robot: %1").arg(dev) : tr("robot: not connected"));
    emit message(on ? tr("Connected to %1").arg(dev) : tr("Disconnected from %1").arg(dev));
    if (on && sim_->isRunning()) sim_poll_.start();
    updateButtons();
  });
  connect(link_, &RobotLink::error, this, &RobotPanel::errorOccurred);
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
    emit sendFinished(ok);
  });
  preview_->setLimits(plannerOptions().limits);
  GuardWheel(this);
  updateButtons();
}

RobotPanel::~RobotPanel() {
  link_->disconnectPort();
  sim_->stop();
}

QWidget* RobotPanel::makePlanBox() {
  const robot::PlannerOptions d;
  auto* box = new QGroupBox(tr("Plan"));
  auto* form = new QFormLayout(box);
  source_ = new QLabel(tr("no angles yet: run the analysis"));
  source_->setWordWrap(true);
  source_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  form->addRow(tr("Angles"), source_);
  mirror_ = new QCheckBox(tr("Mirror (the robot faces the person)"));
  mirror_->setObjectName("mirror");
  form->addRow(mirror_);
  const char* sources[3] = {"J1 = yaw", "J2 = elevation", "J3 = flexion"};
  const robot::JointMap maps[3] = {d.mapping.j1, d.mapping.j2, d.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    sign_[i] = new QComboBox;
    sign_[i]->addItem("+", 1.0);
    sign_[i]->addItem("−", -1.0);
    sign_[i]->setCurrentIndex(maps[i].sign > 0 ? 0 : 1);
    sign_[i]->setObjectName(QString("sign%1").arg(i + 1));
    offset_[i] = DSpin(-360, 360, maps[i].offset_deg, 1, tr("offset, degrees"),
                       QString("offset%1").arg(i + 1));
    auto* row = new QWidget;
    auto* rl = new QHBoxLayout(row);
    rl->setContentsMargins(0, 0, 0, 0);
    rl->addWidget(sign_[i]);
    rl->addWidget(new QLabel(tr("× source +")));
    rl->addWidget(offset_[i], 1);
    map_labels_[i] = new QLabel(tr(sources[i]));
    form->addRow(map_labels_[i], row);
  }
  cutoff_ = DSpin(0, 50, d.cutoff_hz, 2, tr("low-pass cutoff, Hz (0: off)"), "cutoff");
  deadband_ =
      DSpin(0, 90, d.deadband_deg, 1, tr("a new move when a joint changed this much"), "deadband");
  min_interval_ =
      DSpin(0.01, 10, d.min_interval_s, 2, tr("seconds between moves at least"), "minInterval");
  max_gap_ =
      DSpin(0, 60, d.max_gap_s, 2, tr("longest run of lost frames bridged, seconds"), "maxGap");
  clamp_ = new QCheckBox(tr("Clamp to the limits instead of refusing"));
  clamp_->setObjectName("clamp");
  form->addRow(tr("Filter cutoff (Hz)"), cutoff_);
  form->addRow(tr("Deadband (°)"), deadband_);
  form->addRow(tr("Min. interval (s)"), min_interval_);
  form->addRow(tr("Max. gap (s)"), max_gap_);
  form->addRow(clamp_);
  limits_ = new QTableWidget(robot::kJoints, 3);
  limits_->setObjectName("limitsTable");
  limits_->setHorizontalHeaderLabels({tr("min °"), tr("max °"), tr("speed °/s")});
  QStringList rows;
  for (int j = 0; j < robot::kJoints; ++j) {
    rows << QString("J%1").arg(j + 1);
    limits_->setItem(j, 0, new QTableWidgetItem(QString::number(d.limits.min_deg[j])));
    limits_->setItem(j, 1, new QTableWidgetItem(QString::number(d.limits.max_deg[j])));
    limits_->setItem(j, 2, new QTableWidgetItem(QString::number(d.limits.max_speed_deg_s[j])));
  }
  limits_->setVerticalHeaderLabels(rows);
  limits_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  limits_->setMinimumHeight(limits_->verticalHeader()->defaultSectionSize() * 7 + 4);
  form->addRow(tr("Limits"), limits_);
  report_ = new QLabel;
  report_->setObjectName("planReport");
  report_->setWordWrap(true);
  report_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  form->addRow(report_);
  auto replan_later = [this] {
    if (plan_.loaded()) replan();
  };
  for (auto* s : box->findChildren<QDoubleSpinBox*>()) {
    connect(s, &QDoubleSpinBox::valueChanged, this, replan_later);
  }
  for (auto* c : box->findChildren<QComboBox*>()) {
    connect(c, &QComboBox::currentIndexChanged, this, replan_later);
  }
  for (auto* c : box->findChildren<QCheckBox*>())
    connect(c, &QCheckBox::toggled, this, replan_later);
  shown_limits_ = d.limits;
  connect(limits_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    // A cell holds a number of degrees (or degrees per second); anything else is put back.
    double* columns[3] = {shown_limits_.min_deg.data(), shown_limits_.max_deg.data(),
                          shown_limits_.max_speed_deg_s.data()};
    double& kept = columns[item->column()][item->row()];
    bool ok = false;
    const double v = item->text().trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
      const QString typed = item->text();
      {
        const QSignalBlocker block(limits_);
        item->setText(QString::number(kept));
      }
      emit errorOccurred(tr("Limits: '%1' is not a number; J%2 %3 stays %4")
                             .arg(typed)
                             .arg(item->row() + 1)
                             .arg(limits_->horizontalHeaderItem(item->column())->text())
                             .arg(kept));
      return;
    }
    kept = v;
    if (plan_.loaded()) replan();
  });
  return box;
}

QWidget* RobotPanel::makeLinkBox() {
  auto* box = new QGroupBox(tr("Controller"));
  auto* form = new QFormLayout(box);
  port_ = new QComboBox;
  port_->setObjectName("portCombo");
  port_->setEditable(true);
  port_->setToolTip(tr("Serial port (or type a device path)"));
  auto* rescan = new QPushButton(tr("Rescan"));
  auto* prow = new QWidget;
  auto* pl = new QHBoxLayout(prow);
  pl->setContentsMargins(0, 0, 0, 0);
  pl->addWidget(port_, 1);
  pl->addWidget(rescan);
  baud_ = new QComboBox;
  baud_->setObjectName("baudCombo");
  for (int b : {1200, 2400, 4800, 9600, 19200, 38400}) baud_->addItem(QString::number(b), b);
  baud_->setCurrentText("9600");
  sim_speed_ =
      DSpin(0.01, 1.0, 0.1, 2, tr("simulated motion time as a share of real time"), "simSpeed");
  sim_button_ = new QPushButton(tr("Start simulated controller"));
  sim_button_->setObjectName("simButton");
  connect_button_ = new QPushButton(tr("Connect"));
  connect_button_->setObjectName("connectButton");
  send_button_ = new QPushButton(tr("Send to robot…"));
  send_button_->setObjectName("sendButton");
  pause_button_ = new QPushButton(tr("Pause"));
  pause_button_->setCheckable(true);
  pause_button_->setObjectName("pauseButton");
  abort_button_ = new QPushButton(tr("Abort"));
  abort_button_->setObjectName("abortButton");
  send_progress_ = new QProgressBar;
  send_progress_->setObjectName("sendProgress");
  send_progress_->setValue(0);
  replies_ = new QPlainTextEdit;
  replies_->setObjectName("replyLog");
  replies_->setReadOnly(true);
  replies_->setMaximumBlockCount(2000);
  replies_->setMinimumHeight(90);
  replies_->setPlaceholderText(tr("controller replies"));
  auto* srow = new QWidget;
  auto* sl = new QHBoxLayout(srow);
  sl->setContentsMargins(0, 0, 0, 0);
  sl->addWidget(sim_speed_);
  sl->addWidget(sim_button_, 1);
  auto* brow = new QWidget;
  auto* bl = new QHBoxLayout(brow);
  bl->setContentsMargins(0, 0, 0, 0);
  bl->addWidget(send_button_, 1);
  bl->addWidget(pause_button_);
  bl->addWidget(abort_button_);
  form->addRow(tr("Port"), prow);
  form->addRow(tr("Baud"), baud_);
  form->addRow(tr("Simulator"), srow);
  form->addRow(connect_button_);
  form->addRow(brow);
  form->addRow(send_progress_);
  form->addRow(replies_);
  connect(rescan, &QPushButton::clicked, this, &RobotPanel::refreshPorts);
  connect(sim_button_, &QPushButton::clicked, this, [this] {
    if (sim_->isRunning()) {
      link_->disconnectPort();
      sim_->stop();
      sim_poll_.stop();
      emit message(tr("Simulated controller stopped"));
      refreshPorts();
      updateButtons();
    } else {
      startSimulator(sim_speed_->value());
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
  connect(pause_button_, &QPushButton::toggled, link_, &RobotLink::setPaused);
  connect(abort_button_, &QPushButton::clicked, link_, &RobotLink::abort);
  refreshPorts();
  return box;
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
  send_button_->setEnabled(connected && plan_.planned() && !sending);
  pause_button_->setEnabled(sending);
  abort_button_->setEnabled(sending);
  if (!sending) {
    const QSignalBlocker block(pause_button_);
    pause_button_->setChecked(false);
  }
  port_->setEnabled(!connected);
  baud_->setEnabled(!connected);
}

robot::PlannerOptions RobotPanel::plannerOptions() const {
  robot::PlannerOptions o;
  o.mapping = robot::MappingOptions::Default(
      plan_.loaded() ? robot::DetectSourceKind(plan_.angles()) : robot::SourceKind::kArm);
  robot::JointMap* maps[3] = {&o.mapping.j1, &o.mapping.j2, &o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    maps[i]->sign = sign_[i]->currentData().toDouble();
    maps[i]->offset_deg = offset_[i]->value();
  }
  o.mapping.mirror = mirror_->isChecked();
  o.cutoff_hz = cutoff_->value();
  o.deadband_deg = deadband_->value();
  o.min_interval_s = min_interval_->value();
  o.max_interval_s = std::max(o.max_interval_s, o.min_interval_s);
  o.max_gap_s = max_gap_->value();
  o.clamp = clamp_->isChecked();
  for (int j = 0; j < robot::kJoints; ++j) {
    o.limits.min_deg[j] = limits_->item(j, 0)->text().toDouble();
    o.limits.max_deg[j] = limits_->item(j, 1)->text().toDouble();
    o.limits.max_speed_deg_s[j] = limits_->item(j, 2)->text().toDouble();
  }
  return o;
}

void RobotPanel::setPlannerOptions(const robot::PlannerOptions& o) {
  const robot::JointMap maps[3] = {o.mapping.j1, o.mapping.j2, o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    sign_[i]->setCurrentIndex(maps[i].sign > 0 ? 0 : 1);
    offset_[i]->setValue(maps[i].offset_deg);
  }
  mirror_->setChecked(o.mapping.mirror);
  cutoff_->setValue(o.cutoff_hz);
  deadband_->setValue(o.deadband_deg);
  min_interval_->setValue(o.min_interval_s);
  max_gap_->setValue(o.max_gap_s);
  clamp_->setChecked(o.clamp);
  const QSignalBlocker block(limits_);
  shown_limits_ = o.limits;
  for (int j = 0; j < robot::kJoints; ++j) {
    limits_->item(j, 0)->setText(QString::number(o.limits.min_deg[j]));
    limits_->item(j, 1)->setText(QString::number(o.limits.max_deg[j]));
    limits_->item(j, 2)->setText(QString::number(o.limits.max_speed_deg_s[j]));
  }
  if (plan_.loaded()) replan();
}

void RobotPanel::setAngleFile(const QString& path) {
  animate_button_->setChecked(false);
  if (path.isEmpty()) {
    plan_.Clear();
    source_->setText(tr("no angles yet: run the analysis"));
    report_->clear();
    updateButtons();
    return;
  }
  const Status st = plan_.Load(path.toStdString());
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    updateButtons();
    return;
  }
  source_->setText(tr("%1 rows (%2)")
                       .arg(plan_.angles().rows.size())
                       .arg(QString::fromStdString(plan_.angles().Meta("engine", "?"))));
  followFileKind(robot::DetectSourceKind(plan_.angles()));
  replan();
}

void RobotPanel::setMappingKind(robot::SourceKind kind) {
  mapping_kind_ = kind;
  const bool marker = kind == robot::SourceKind::kMarker;
  map_labels_[1]->setText(marker ? tr("J2 = bend") : tr("J2 = elevation"));
  map_labels_[2]->setText(marker ? tr("J3 (held)") : tr("J3 = flexion"));
}

// As `plan` does on the command line: mapping rows left at one kind's defaults switch to the
// defaults of the new file's kind (marker views drive J2 by the bend, arm files by the
// elevation). Rows the operator changed are kept, and Messages says so.
void RobotPanel::followFileKind(robot::SourceKind kind) {
  if (kind == mapping_kind_) return;
  const robot::MappingOptions old_defaults = robot::MappingOptions::Default(mapping_kind_);
  const robot::JointMap old_maps[3] = {old_defaults.j1, old_defaults.j2, old_defaults.j3};
  bool untouched = true;
  for (int i = 0; i < 3; ++i) {
    untouched = untouched && sign_[i]->currentData().toDouble() == old_maps[i].sign &&
                offset_[i]->value() == old_maps[i].offset_deg;
  }
  setMappingKind(kind);
  const bool marker = kind == robot::SourceKind::kMarker;
  if (!untouched) {
    emit message(tr("Robot mapping: your J1-J3 settings are kept for this %1 file; the defaults "
                    "for it differ")
                     .arg(marker ? tr("marker") : tr("arm")));
    return;
  }
  const robot::MappingOptions d = robot::MappingOptions::Default(kind);
  const robot::JointMap maps[3] = {d.j1, d.j2, d.j3};
  for (int i = 0; i < 3; ++i) {
    const QSignalBlocker block_sign(sign_[i]), block_offset(offset_[i]);
    sign_[i]->setCurrentIndex(maps[i].sign > 0 ? 0 : 1);
    offset_[i]->setValue(maps[i].offset_deg);
  }
}

bool RobotPanel::replan() {
  const robot::PlannerOptions options = plannerOptions();
  preview_->setLimits(options.limits);
  const std::vector<LimitViolation> bad = plan_.Violations(options);
  QString violations;
  if (!bad.empty()) {
    violations = tr("<br><font color='#d03b2f'>%1 frame(s) map outside the limits, first: frame "
                    "%2 J%3 = %4°</font>")
                     .arg(bad.size())
                     .arg(bad.front().frame)
                     .arg(bad.front().joint + 1)
                     .arg(bad.front().deg, 0, 'f', 1);
  }
  const Status st = options.Check() ? plan_.Plan(options) : options.Check();
  if (!st) {
    report_->setText(tr("<font color='#d03b2f'>Not planned: %1</font>")
                         .arg(QString::fromStdString(st.message()).toHtmlEscaped()) +
                     violations);
    // Planning runs on its own after every analysis and settings change: the reason stays in
    // the plan report (red) and is noted once in Messages, without raising an error the
    // operator did not ask for. Sending or exporting a refused plan is the error.
    const QString why = QString::fromStdString(st.message());
    if (why != last_plan_failure_) emit message(tr("Robot plan not made: %1").arg(why));
    last_plan_failure_ = why;
    updateButtons();
    showPose();
    return false;
  }
  last_plan_failure_.clear();
  const robot::PlanReport& r = plan_.report();
  report_->setText(tr("%1 moves over %2 s (%3 rows used, %4 filled, %5 clamped, +%6 s for speed)")
                       .arg(plan_.trajectory().keyframes.size())
                       .arg(plan_.trajectory().duration_s(), 0, 'f', 1)
                       .arg(r.used_rows)
                       .arg(r.filled_rows)
                       .arg(r.clamped_rows)
                       .arg(r.stretch_s, 0, 'f', 1) +
                   // Still images (marker views) have no frame rate: the planner leaves
                   // them unfiltered, whatever the cutoff setting.
                   (r.filter_cutoff_hz == 0 && options.cutoff_hz > 0
                        ? tr("<br>Still images: no low-pass filter.")
                        : QString()) +
                   violations);
  updateButtons();
  showPose();
  return true;
}

void RobotPanel::setVideoFrame(int frame) {
  video_frame_ = frame;
  showPose();
}

void RobotPanel::showPose() {
  if (animate_.isActive()) return;
  if (sim_->isRunning() && link_->isConnected()) return;  // the poll shows the controller
  robot::JointArray j;
  if (plan_.loaded() && plan_.MappedPose(video_frame_, plannerOptions(), &j)) {
    preview_->setPose(j, tr("frame %1 (mapped, unfiltered)").arg(video_frame_));
  } else if (plan_.planned()) {
    const int k = plan_.KeyframeForFrame(video_frame_);
    preview_->setPose(plan_.trajectory().keyframes[std::max(0, k)].joint_deg,
                      tr("plan near frame %1").arg(video_frame_));
  }
}

bool RobotPanel::exportVal(const QString& path) {
  std::vector<NamedPath> inputs = inputs_ ? inputs_() : std::vector<NamedPath>();
  if (!plan_.angle_path().empty()) inputs.push_back({"the angle file", plan_.angle_path()});
  Status st = CheckOutputsAreNotInputs(inputs, {{"the VAL program", path.toStdString()}});
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  std::string text;
  st = plan_.ValText(profile_, &text);
  if (st) st = WriteFileAtomically(path.toStdString(), text);
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  emit message(tr("Exported the VAL program to %1").arg(path));
  return true;
}

void RobotPanel::exportValInteractive() {
  if (!plan_.planned()) {
    emit errorOccurred(tr("No plan to export: run the analysis, then check the Robot panel"));
    return;
  }
  const QString path = QFileDialog::getSaveFileName(this, tr("Export VAL program"),
                                                    RecentFiles::lastDir() + "/program.val",
                                                    tr("VAL programs (*.val)"));
  if (!path.isEmpty()) exportVal(path);
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
  return link_->connectPort(device, baud_->currentData().toInt());
}

bool RobotPanel::sendPlan(bool confirmed) {
  if (!plan_.planned()) {
    emit errorOccurred(
        last_plan_failure_.isEmpty()
            ? tr("Nothing to send: no plan (run the analysis first)")
            : tr("Nothing to send: the plan was refused: %1").arg(last_plan_failure_));
    return false;
  }
  std::string text;
  Status st = plan_.ValText(profile_, &text);
  robot::ValProgram program;
  if (st) {
    std::istringstream in(text);
    st = robot::ParseValProgram(in, "plan.val", profile_.max_line_length, &program);
  }
  if (st) {
    robot::SafetyState safety = robot::SafetyState::For(plan_.options().limits, profile_);
    st = robot::CheckProgram(program, safety);
  }
  if (!st) {
    emit errorOccurred(QString::fromStdString(st.message()));
    return false;
  }
  if (!confirmed) {
    const QString ranges =
        QString::fromStdString(DescribeJointRanges(plan_.report(), plan_.options().limits));
    QMessageBox box(QMessageBox::Warning, tr("Move the robot?"),
                    tr("Send %1 lines to %2? The arm will move through these joint ranges:")
                        .arg(program.lines.size())
                        .arg(link_->device()),
                    QMessageBox::Cancel, this);
    box.setInformativeText("<pre>" + ranges.toHtmlEscaped() + "</pre>");
    box.addButton(tr("Move the robot"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    if (box.exec() == QMessageBox::Cancel) return false;
  }
  replies_->clear();
  const bool ok = link_->send(program, profile_, plan_.options().limits);
  if (ok) emit linkStateChanged(tr("robot: sending to %1").arg(link_->device()));
  updateButtons();
  return ok;
}

QString RobotPanel::replyLog() const { return replies_->toPlainText(); }

void RobotPanel::save(QSettings& s) const {
  const robot::PlannerOptions o = plannerOptions();
  s.beginGroup("robot");
  s.setValue("mappingKind", robot::SourceKindName(mapping_kind_));
  s.setValue("mirror", o.mapping.mirror);
  const robot::JointMap maps[3] = {o.mapping.j1, o.mapping.j2, o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    s.setValue(QString("j%1/sign").arg(i + 1), maps[i].sign);
    s.setValue(QString("j%1/offset").arg(i + 1), maps[i].offset_deg);
  }
  s.setValue("cutoff", o.cutoff_hz);
  s.setValue("deadband", o.deadband_deg);
  s.setValue("minInterval", o.min_interval_s);
  s.setValue("maxGap", o.max_gap_s);
  s.setValue("clamp", o.clamp);
  QVariantList mins, maxs, speeds;
  for (int j = 0; j < robot::kJoints; ++j) {
    mins << o.limits.min_deg[j];
    maxs << o.limits.max_deg[j];
    speeds << o.limits.max_speed_deg_s[j];
  }
  s.setValue("limitsMin", mins);
  s.setValue("limitsMax", maxs);
  s.setValue("speedLimits", speeds);
  s.setValue("port", port_->currentText());
  s.setValue("baud", baud_->currentData());
  s.endGroup();
}

void RobotPanel::load(QSettings& s) {
  robot::PlannerOptions o = plannerOptions();
  s.beginGroup("robot");
  // The J1-J3 rows were saved showing this kind's mapping (its defaults, or changes to them).
  const robot::SourceKind saved_kind =
      s.value("mappingKind").toString() ==
              QLatin1String(robot::SourceKindName(robot::SourceKind::kMarker))
          ? robot::SourceKind::kMarker
          : robot::SourceKind::kArm;
  o.mapping.mirror = s.value("mirror", false).toBool();
  robot::JointMap* maps[3] = {&o.mapping.j1, &o.mapping.j2, &o.mapping.j3};
  for (int i = 0; i < 3; ++i) {
    maps[i]->sign = s.value(QString("j%1/sign").arg(i + 1), maps[i]->sign).toDouble() < 0 ? -1 : 1;
    maps[i]->offset_deg = s.value(QString("j%1/offset").arg(i + 1), maps[i]->offset_deg).toDouble();
  }
  o.cutoff_hz = s.value("cutoff", o.cutoff_hz).toDouble();
  o.deadband_deg = s.value("deadband", o.deadband_deg).toDouble();
  o.min_interval_s = s.value("minInterval", o.min_interval_s).toDouble();
  o.max_gap_s = s.value("maxGap", o.max_gap_s).toDouble();
  o.clamp = s.value("clamp", false).toBool();
  const QVariantList mins = s.value("limitsMin").toList();
  const QVariantList maxs = s.value("limitsMax").toList();
  const QVariantList speeds = s.value("speedLimits").toList();
  if (mins.size() == robot::kJoints && maxs.size() == robot::kJoints &&
      speeds.size() == robot::kJoints) {
    for (int j = 0; j < robot::kJoints; ++j) {
      o.limits.min_deg[j] = mins[j].toDouble();
      o.limits.max_deg[j] = maxs[j].toDouble();
      o.limits.max_speed_deg_s[j] = speeds[j].toDouble();
    }
  }
  const QString port = s.value("port").toString();
  const int baud = baud_->findData(s.value("baud", 9600));
  s.endGroup();
  setMappingKind(saved_kind);
  setPlannerOptions(o);
  if (plan_.loaded()) {
    followFileKind(robot::DetectSourceKind(plan_.angles()));
    replan();
  }
  if (!port.isEmpty() && !port.contains("(simulated)")) port_->setEditText(port);
  if (baud >= 0) baud_->setCurrentIndex(baud);
}

}  // namespace armmimic::gui
