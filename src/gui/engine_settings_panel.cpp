#include "engine_settings_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include "parameter_form.h"
#include "wheel_guard.h"

namespace armmimic::gui {
namespace {

enum BgMode { kBgImage = 0, kBgFrames = 1, kBgNone = 2 };

QSpinBox* Spin(int lo, int hi, int value, const QString& tip, const QString& name) {
  auto* s = new QSpinBox;
  s->setRange(lo, hi);
  s->setValue(value);
  s->setToolTip(tip);
  s->setObjectName(name);
  return s;
}

QDoubleSpinBox* DSpin(double lo, double hi, double value, int decimals, const QString& tip,
                      const QString& name) {
  auto* s = new QDoubleSpinBox;
  s->setRange(lo, hi);
  s->setDecimals(decimals);
  s->setValue(value);
  s->setToolTip(tip);
  s->setObjectName(name);
  return s;
}

}  // namespace

EngineSettingsPanel::EngineSettingsPanel(QWidget* parent)
    : QWidget(parent), engine_(new QComboBox), pages_(new QStackedWidget) {
  engine_->setObjectName("engineCombo");
  makeForms();
  auto* params = new QGroupBox(tr("Engine parameters"));
  auto* pl = new QVBoxLayout(params);
  pl->addWidget(pages_);
  auto* layout = new QVBoxLayout(this);
  auto* top = new QFormLayout;
  top->addRow(tr("Engine"), engine_);
  layout->addLayout(top);
  QWidget* inputs = makeInputs();
  layout->addWidget(inputs);
  layout->addWidget(params);
  layout->addStretch();
  connect(engine_, &QComboBox::currentIndexChanged, this, [this](int i) {
    placeForms(static_cast<EngineKind>(engine_->itemData(i).toInt()));
    pages_->setCurrentIndex(i);
    updateEnabled();
    // The marker engine takes no region or shoulder: the video stops showing them, and shows
    // them again for an arm engine.
    emit roiChanged(options().roi);
    emit shoulderChanged(options().shoulder_px);
    emit changed();
  });
  for (auto* spin : inputs->findChildren<QAbstractSpinBox*>()) {
    if (auto* s = qobject_cast<QSpinBox*>(spin)) {
      connect(s, &QSpinBox::valueChanged, this, &EngineSettingsPanel::changed);
    } else if (auto* d = qobject_cast<QDoubleSpinBox*>(spin)) {
      connect(d, &QDoubleSpinBox::valueChanged, this, &EngineSettingsPanel::changed);
    }
  }
  for (auto* e : inputs->findChildren<QLineEdit*>()) {
    connect(e, &QLineEdit::textChanged, this, &EngineSettingsPanel::changed);
  }
  auto roi_changed = [this] { emit roiChanged(options().roi); };
  connect(roi_box_, &QGroupBox::toggled, this, roi_changed);
  for (QSpinBox* s : roi_) connect(s, &QSpinBox::valueChanged, this, roi_changed);
  auto shoulder_changed = [this] { emit shoulderChanged(options().shoulder_px); };
  connect(shoulder_box_, &QGroupBox::toggled, this, shoulder_changed);
  connect(shoulder_x_, &QDoubleSpinBox::valueChanged, this, shoulder_changed);
  connect(shoulder_y_, &QDoubleSpinBox::valueChanged, this, shoulder_changed);
  connect(elbow_wrist_box_, &QGroupBox::toggled, this, &EngineSettingsPanel::changed);
  connect(auto_calibrate_, &QPushButton::clicked, this,
          &EngineSettingsPanel::autoCalibrateRequested);
  // Calibrate needs the protocol's background and arm-length image, typed or chosen.
  connect(background_, &QLineEdit::textChanged, this, &EngineSettingsPanel::updateEnabled);
  connect(arm_length_, &QLineEdit::textChanged, this, &EngineSettingsPanel::updateEnabled);
  GuardWheel(this);
  updateEnabled();
}

QLineEdit* EngineSettingsPanel::fileRow(QWidget* parent, const QString& name, QWidget** row) {
  *row = new QWidget(parent);
  auto* edit = new QLineEdit(*row);
  edit->setObjectName(name);
  edit->setPlaceholderText(tr("image file"));
  auto* browse = new QToolButton(*row);
  browse->setText("…");
  browse->setToolTip(tr("Choose an image"));
  auto* l = new QHBoxLayout(*row);
  l->setContentsMargins(0, 0, 0, 0);
  l->addWidget(edit, 1);
  l->addWidget(browse);
  connect(browse, &QToolButton::clicked, this, [this, edit] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Choose an image"), edit->text(), tr("Images (*.png *.jpg *.jpeg *.bmp *.tif)"));
    if (!path.isEmpty()) edit->setText(path);
  });
  return edit;
}

QWidget* EngineSettingsPanel::makeInputs() {
  auto* box = new QGroupBox(tr("Inputs"));
  auto* form = new QFormLayout(box);
  bg_mode_ = new QComboBox;
  bg_mode_->setObjectName("backgroundMode");
  bg_mode_->addItem(tr("Background image"));
  bg_mode_->addItem(tr("Average the first K frames"));
  bg_mode_->addItem(tr("None (shoulder set by hand)"));
  background_ = fileRow(box, "backgroundPath", &background_row_);
  bg_frames_ =
      Spin(1, 100000, 45, tr("--background-frames: frames [0, K) averaged"), "backgroundFrames");
  arm_length_ = fileRow(box, "armLengthPath", &arm_length_row_);
  reference_ = fileRow(box, "referencePath", &reference_row_);
  start_ = Spin(0, 10000000, 0, tr("--start: first standstill frame"), "startFrame");
  shoulder_box_ = new QGroupBox(tr("Fixed shoulder"));
  shoulder_box_->setToolTip(tr("--shoulder: the shoulder in pixels, instead of the standstill's"));
  shoulder_box_->setCheckable(true);
  shoulder_box_->setChecked(false);
  shoulder_box_->setObjectName("shoulderBox");
  shoulder_x_ = DSpin(0, 100000, 0, 1, tr("x, pixels"), "shoulderX");
  shoulder_y_ = DSpin(0, 100000, 0, 1, tr("y, pixels"), "shoulderY");
  auto* sl = new QHBoxLayout(shoulder_box_);
  sl->addWidget(new QLabel("x"));
  sl->addWidget(shoulder_x_, 1);
  sl->addWidget(new QLabel("y"));
  sl->addWidget(shoulder_y_, 1);
  // The elbow and wrist of the start frame (lk, hybrid): clicked, typed, dragged or calibrated.
  elbow_wrist_box_ = new QGroupBox(tr("Elbow and wrist"));
  elbow_wrist_box_->setToolTip(tr("--elbow, --wrist: the joints in the start frame (lk, hybrid)"));
  elbow_wrist_box_->setCheckable(true);
  elbow_wrist_box_->setChecked(false);
  elbow_wrist_box_->setObjectName("elbowWristBox");
  auto* ew = new QFormLayout(elbow_wrist_box_);
  const char* axes[2] = {"X", "Y"};
  for (int joint = 0; joint < 2; ++joint) {
    QDoubleSpinBox** spins = joint == 0 ? elbow_ : wrist_;
    auto* row = new QHBoxLayout;
    for (int i = 0; i < 2; ++i) {
      spins[i] =
          DSpin(0, 100000, 0, 1, tr("pixels"), QString(joint == 0 ? "elbow" : "wrist") + axes[i]);
      row->addWidget(new QLabel(QString(axes[i]).toLower()));
      row->addWidget(spins[i], 1);
    }
    ew->addRow(joint == 0 ? tr("Elbow") : tr("Wrist"), row);
  }
  auto_calibrate_ = new QPushButton(tr("Auto-calibrate"));
  auto_calibrate_->setObjectName("autoCalibrate");
  auto_calibrate_->setToolTip(
      tr("--auto-calibrate: the shoulder, elbow and wrist in the start frame from the pose "
         "network (the better-seen arm)"));
  roi_box_ = new QGroupBox(tr("Region of interest"));
  roi_box_->setToolTip(tr("--roi: analyse only this rectangle"));
  roi_box_->setCheckable(true);
  roi_box_->setChecked(false);
  roi_box_->setObjectName("roiBox");
  auto* rl = new QHBoxLayout(roi_box_);
  const char* roi_names[4] = {"x", "y", "w", "h"};
  for (int i = 0; i < 4; ++i) {
    roi_[i] = Spin(i < 2 ? 0 : 1, 100000, i < 2 ? 0 : 1, tr("pixels"),
                   QString("roi") + QChar(roi_names[i][0]).toUpper());
    rl->addWidget(new QLabel(roi_names[i]));
    rl->addWidget(roi_[i], 1);
  }
  form->addRow(tr("Background"), bg_mode_);
  form->addRow(tr("Background image"), background_row_);
  form->addRow(tr("Frames K"), bg_frames_);
  form->addRow(tr("Arm-length image"), arm_length_row_);
  form->addRow(tr("Reference image"), reference_row_);
  form->addRow(tr("Start frame"), start_);
  form->addRow(shoulder_box_);
  form->addRow(elbow_wrist_box_);
  form->addRow(auto_calibrate_);
  form->addRow(makeCalibrateRow());
  form->addRow(roi_box_);
  connect(bg_mode_, &QComboBox::currentIndexChanged, this, [this] {
    updateEnabled();
    emit changed();
  });
  return box;
}

void EngineSettingsPanel::updateEnabled() {
  const auto kind = static_cast<EngineKind>(engine_->currentData().toInt());
  const bool marker = kind == EngineKind::kMarker;
  // The pose network needs no background: its mode, image (with its "…" button) and frames are
  // greyed with the rest of what it does not read.
  const bool background = !marker && kind != EngineKind::kPose;
  bg_mode_->setEnabled(background);
  background_row_->setEnabled(background && bg_mode_->currentIndex() == kBgImage);
  bg_frames_->setEnabled(background && bg_mode_->currentIndex() == kBgFrames);
  // The tracking engines (lk, and hybrid, which runs it) take the clicked or estimated joints.
  const bool tracking = kind == EngineKind::kLk || kind == EngineKind::kHybrid;
  arm_length_row_->setEnabled(kind == EngineKind::kBgsub || tracking);
  reference_row_->setEnabled(marker);
  start_->setEnabled(!marker);
  shoulder_box_->setEnabled(!marker && kind != EngineKind::kPose);
  elbow_wrist_box_->setEnabled(tracking);
  auto_calibrate_->setEnabled(tracking);
  const bool has_background =
      (bg_mode_->currentIndex() == kBgImage && !background_->text().isEmpty()) ||
      bg_mode_->currentIndex() == kBgFrames;
  standstill_calibrate_->setEnabled(tracking && has_background && !arm_length_->text().isEmpty());
  accept_estimate_->setEnabled(estimate_shown_);
  roi_box_->setEnabled(!marker);
}

AnalysisOptions EngineSettingsPanel::options() const {
  AnalysisOptions o = base_;
  o.inputs.clear();
  o.background_path.clear();
  o.background_frames = 0;
  o.arm_length_path.clear();
  o.reference_path.clear();
  o.start = 0;
  o.shoulder_px.reset();
  o.roi.reset();
  o.engine.kind = static_cast<EngineKind>(engine_->currentData().toInt());
  for (ParameterForm* form : forms_) form->apply(&o.engine);
  const bool marker = o.engine.kind == EngineKind::kMarker;
  if (marker) {
    o.reference_path = reference_->text().toStdString();
    return o;
  }
  if (bg_mode_->currentIndex() == kBgImage) o.background_path = background_->text().toStdString();
  if (bg_mode_->currentIndex() == kBgFrames) {
    o.background_frames = bg_frames_->value();
  }
  const bool tracking = o.engine.kind == EngineKind::kLk || o.engine.kind == EngineKind::kHybrid;
  if (o.engine.kind == EngineKind::kBgsub || tracking) {
    o.arm_length_path = arm_length_->text().toStdString();
  }
  o.start = start_->value();
  if (o.engine.kind == EngineKind::kPose) {
    o.background_path.clear();
    o.background_frames = 0;
  } else if (shoulder_box_->isChecked()) {
    o.shoulder_px = cv::Point2d(shoulder_x_->value(), shoulder_y_->value());
  }
  o.elbow_px.reset();
  o.wrist_px.reset();
  if (tracking && shoulder_box_->isChecked() && elbow_wrist_box_->isChecked()) {
    o.elbow_px = cv::Point2d(elbow_[0]->value(), elbow_[1]->value());
    o.wrist_px = cv::Point2d(wrist_[0]->value(), wrist_[1]->value());
  }
  if (roi_box_->isChecked()) {
    o.roi = cv::Rect(roi_[0]->value(), roi_[1]->value(), roi_[2]->value(), roi_[3]->value());
  }
  return o;
}

void EngineSettingsPanel::setOptions(const AnalysisOptions& o) {
  base_ = o;
  engine_->setCurrentIndex(engine_->findData(int(o.engine.kind)));
  for (ParameterForm* form : forms_) form->setValues(o.engine);
  if (!o.background_path.empty()) {
    bg_mode_->setCurrentIndex(kBgImage);
  } else if (o.background_frames > 0) {
    bg_mode_->setCurrentIndex(kBgFrames);
  } else if (o.engine.kind != EngineKind::kMarker) {
    bg_mode_->setCurrentIndex(kBgNone);
  }
  background_->setText(QString::fromStdString(o.background_path));
  if (o.background_frames > 0) bg_frames_->setValue(o.background_frames);
  arm_length_->setText(QString::fromStdString(o.arm_length_path));
  reference_->setText(QString::fromStdString(o.reference_path));
  start_->setValue(o.start);
  setShoulder(o.shoulder_px);
  if (o.elbow_px && o.wrist_px) {
    elbow_[0]->setValue(o.elbow_px->x);
    elbow_[1]->setValue(o.elbow_px->y);
    wrist_[0]->setValue(o.wrist_px->x);
    wrist_[1]->setValue(o.wrist_px->y);
  }
  elbow_wrist_box_->setChecked(o.elbow_px && o.wrist_px);
  setRoi(o.roi);
  updateEnabled();
}

void EngineSettingsPanel::setRoi(const std::optional<cv::Rect>& roi) {
  if (roi) {
    const int v[4] = {roi->x, roi->y, roi->width, roi->height};
    for (int i = 0; i < 4; ++i) {
      const QSignalBlocker block(roi_[i]);
      roi_[i]->setValue(v[i]);
    }
  }
  roi_box_->setChecked(roi.has_value());  // emits roiChanged when it flips
  emit roiChanged(options().roi);
}

void EngineSettingsPanel::setShoulder(const std::optional<cv::Point2d>& s) {
  if (s) {
    const QSignalBlocker bx(shoulder_x_), by(shoulder_y_);
    shoulder_x_->setValue(s->x);
    shoulder_y_->setValue(s->y);
  }
  shoulder_box_->setChecked(s.has_value());
  emit shoulderChanged(options().shoulder_px);
}

void EngineSettingsPanel::setJoint(int joint, const cv::Point2d& px) {
  if (joint == 0) {
    setShoulder(px);
    return;
  }
  QDoubleSpinBox** spins = joint == 1 ? elbow_ : wrist_;
  spins[0]->setValue(px.x);
  spins[1]->setValue(px.y);
  elbow_wrist_box_->setChecked(true);
  emit changed();
}

void EngineSettingsPanel::setBackgroundImage(const QString& path) {
  background_->setText(path);
  bg_mode_->setCurrentIndex(kBgImage);
}

void EngineSettingsPanel::save(QSettings& s) const {
  const AnalysisOptions o = options();
  s.beginGroup("analysis");
  s.setValue("engine", engine_->currentData().toInt());
  s.setValue("backgroundMode", bg_mode_->currentIndex());
  s.setValue("background", background_->text());
  s.setValue("backgroundFrames", bg_frames_->value());
  s.setValue("armLength", arm_length_->text());
  s.setValue("reference", reference_->text());
  s.setValue("start", start_->value());
  for (const ParameterForm* form : forms_) form->save(s, o.engine);
  s.endGroup();
}

void EngineSettingsPanel::load(QSettings& s) {
  s.beginGroup("analysis");
  AnalysisOptions o;
  const int last_kind = static_cast<int>(AllEngineKinds().size()) - 1;
  o.engine.kind = static_cast<EngineKind>(
      std::clamp(s.value("engine", int(EngineKind::kBgsub)).toInt(), 0, last_kind));
  for (const ParameterForm* form : forms_) form->load(s, &o.engine);
  o.arm_length_path = s.value("armLength").toString().toStdString();
  o.reference_path = s.value("reference").toString().toStdString();
  o.start = s.value("start", 0).toInt();
  setOptions(o);
  background_->setText(s.value("background").toString());
  bg_frames_->setValue(s.value("backgroundFrames", 45).toInt());
  bg_mode_->setCurrentIndex(std::clamp(s.value("backgroundMode", 0).toInt(), 0, 2));
  s.endGroup();
  updateEnabled();
}

}  // namespace armmimic::gui
