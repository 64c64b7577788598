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
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

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
  engine_->addItem(tr("Background subtraction (ch. 5)"), int(EngineKind::kBgsub));
  engine_->addItem(tr("Lucas–Kanade tracking (ch. 6)"), int(EngineKind::kLk));
  engine_->addItem(tr("Marker joint (ch. 4)"), int(EngineKind::kMarker));
  pages_->addWidget(makeEnginePage(EngineKind::kBgsub, BgsubOptionFields(), &EngineOptions::bgsub));
  pages_->addWidget(makeEnginePage(EngineKind::kLk, LkOptionFields(), &EngineOptions::lk));
  pages_->addWidget(
      makeEnginePage(EngineKind::kMarker, MarkerOptionFields(), &EngineOptions::marker));
  auto* params = new QGroupBox(tr("Engine parameters"));
  auto* pl = new QVBoxLayout(params);
  pl->addWidget(pages_);
  auto* layout = new QVBoxLayout(this);
  auto* top = new QFormLayout;
  top->addRow(tr("Engine"), engine_);
  layout->addLayout(top);
  layout->addWidget(makeInputs());
  layout->addWidget(params);
  layout->addStretch();
  connect(engine_, &QComboBox::currentIndexChanged, this, [this](int i) {
    pages_->setCurrentIndex(i);
    updateEnabled();
    emit changed();
  });
  for (auto* spin : findChildren<QAbstractSpinBox*>()) {
    if (auto* s = qobject_cast<QSpinBox*>(spin)) {
      connect(s, &QSpinBox::valueChanged, this, &EngineSettingsPanel::changed);
    } else if (auto* d = qobject_cast<QDoubleSpinBox*>(spin)) {
      connect(d, &QDoubleSpinBox::valueChanged, this, &EngineSettingsPanel::changed);
    }
  }
  for (auto* c : findChildren<QCheckBox*>()) {
    connect(c, &QCheckBox::toggled, this, &EngineSettingsPanel::changed);
  }
  for (auto* e : findChildren<QLineEdit*>()) {
    connect(e, &QLineEdit::textChanged, this, &EngineSettingsPanel::changed);
  }
  auto roi_changed = [this] { emit roiChanged(options().roi); };
  connect(roi_box_, &QGroupBox::toggled, this, roi_changed);
  for (QSpinBox* s : roi_) connect(s, &QSpinBox::valueChanged, this, roi_changed);
  auto shoulder_changed = [this] { emit shoulderChanged(options().shoulder_px); };
  connect(shoulder_box_, &QGroupBox::toggled, this, shoulder_changed);
  connect(shoulder_x_, &QDoubleSpinBox::valueChanged, this, shoulder_changed);
  connect(shoulder_y_, &QDoubleSpinBox::valueChanged, this, shoulder_changed);
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
  shoulder_box_ = new QGroupBox(tr("Fixed shoulder (--shoulder)"));
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
  roi_box_ = new QGroupBox(tr("Region of interest (--roi)"));
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
  form->addRow(roi_box_);
  connect(bg_mode_, &QComboBox::currentIndexChanged, this, [this] {
    updateEnabled();
    emit changed();
  });
  return box;
}

template <typename O>
QWidget* EngineSettingsPanel::makeEnginePage(EngineKind engine,
                                             const std::vector<OptionField<O>>& fields,
                                             O EngineOptions::*member) {
  const QString name = EngineName(engine);
  auto* page = new QWidget;
  auto* v = new QVBoxLayout(page);
  v->setContentsMargins(0, 0, 0, 0);
  auto* main_form = new QFormLayout;
  auto* advanced = new QWidget;
  advanced->setObjectName(name + "Advanced");
  auto* advanced_form = new QFormLayout(advanced);
  advanced_form->setContentsMargins(12, 0, 0, 0);
  advanced_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  int advanced_count = 0;
  for (const OptionField<O>& f : fields) {
    if (f.group == OptionGroup::kInput) continue;  // an analysis input, edited with the inputs
    const QString label = QString::fromStdString(f.label);
    QString tip = QString::fromStdString(f.help);
    QWidget* editor = nullptr;
    switch (f.kind) {
      case OptionKind::kInt: {
        auto* spin = new QSpinBox;
        spin->setRange(int(f.min), int(f.max));
        spin->setSingleStep(int(f.step));
        editor = spin;
        tip += tr("\nDefault %1, range %2 to %3").arg(f.default_value).arg(f.min).arg(f.max);
        break;
      }
      case OptionKind::kDouble: {
        auto* spin = new QDoubleSpinBox;
        spin->setDecimals(f.decimals);
        spin->setRange(f.min, f.max);
        spin->setSingleStep(f.step);
        editor = spin;
        tip += tr("\nDefault %1, range %2 to %3")
                   .arg(f.default_value, 0, 'g', 6)
                   .arg(f.min)
                   .arg(f.max);
        break;
      }
      case OptionKind::kBool:
        editor = new QCheckBox(label);
        tip += f.default_value != 0 ? tr("\nDefault: on") : tr("\nDefault: off");
        break;
      case OptionKind::kEnum: {
        auto* combo = new QComboBox;
        for (const std::string& c : f.choices) combo->addItem(QString::fromStdString(c));
        connect(combo, &QComboBox::currentIndexChanged, this, &EngineSettingsPanel::changed);
        editor = combo;
        tip += tr("\nDefault: %1").arg(QString::fromStdString(f.choices[int(f.default_value)]));
        break;
      }
    }
    editor->setObjectName(name + "." + QString::fromStdString(f.key));
    editor->setToolTip(tip);
    editor->setFocusPolicy(Qt::StrongFocus);
    QFormLayout* form = f.group == OptionGroup::kMain ? main_form : advanced_form;
    if (f.group == OptionGroup::kAdvanced) ++advanced_count;
    if (f.kind == OptionKind::kBool) {
      form->addRow(editor);
    } else {
      auto* l = new QLabel(label);
      l->setToolTip(tip);
      form->addRow(l, editor);
    }
    ParamEditor p{engine, f.key,     f.kind, f.group, f.decimals, f.min,
                  f.max,  f.choices, editor, nullptr, nullptr};
    const auto get = f.get;
    const auto set = f.set;
    p.get = [get, member](const EngineOptions& o) { return get(o.*member); };
    p.set = [set, member](EngineOptions& o, double value) { set(o.*member, value); };
    params_.push_back(std::move(p));
    setEditorValue(params_.back(), f.default_value);
  }
  auto* toggle = new QToolButton;
  toggle->setObjectName(name + "AdvancedToggle");
  toggle->setText(tr("Advanced (%1 more)").arg(advanced_count));
  toggle->setToolTip(tr("Every other parameter of this engine"));
  toggle->setCheckable(true);
  toggle->setAutoRaise(true);
  toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  toggle->setArrowType(Qt::RightArrow);
  advanced->setVisible(false);
  connect(toggle, &QToolButton::toggled, this, [toggle, advanced](bool on) {
    toggle->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    advanced->setVisible(on);
  });
  advanced_[int(engine)] = toggle;
  v->addLayout(main_form);
  v->addWidget(toggle);
  v->addWidget(advanced);
  return page;
}

double EngineSettingsPanel::editorValue(const ParamEditor& p) const {
  switch (p.kind) {
    case OptionKind::kInt:
      return static_cast<QSpinBox*>(p.widget)->value();
    case OptionKind::kDouble:
      return static_cast<QDoubleSpinBox*>(p.widget)->value();
    case OptionKind::kBool:
      return static_cast<QCheckBox*>(p.widget)->isChecked() ? 1 : 0;
    case OptionKind::kEnum:
      return static_cast<QComboBox*>(p.widget)->currentIndex();
  }
  return 0;
}

void EngineSettingsPanel::setEditorValue(const ParamEditor& p, double value) {
  switch (p.kind) {
    case OptionKind::kInt:
      static_cast<QSpinBox*>(p.widget)->setValue(int(std::lround(value)));
      break;
    case OptionKind::kDouble:
      static_cast<QDoubleSpinBox*>(p.widget)->setValue(value);
      break;
    case OptionKind::kBool:
      static_cast<QCheckBox*>(p.widget)->setChecked(value != 0);
      break;
    case OptionKind::kEnum:
      static_cast<QComboBox*>(p.widget)->setCurrentIndex(int(std::lround(value)));
      break;
  }
}

QWidget* EngineSettingsPanel::parameterEditor(EngineKind engine, const QString& key) const {
  for (const ParamEditor& p : params_) {
    if (p.engine == engine && QString::fromStdString(p.key) == key) return p.widget;
  }
  return nullptr;
}

QToolButton* EngineSettingsPanel::advancedToggle(EngineKind engine) const {
  return advanced_[int(engine)];
}

void EngineSettingsPanel::updateEnabled() {
  const auto kind = static_cast<EngineKind>(engine_->currentData().toInt());
  const bool marker = kind == EngineKind::kMarker;
  bg_mode_->setEnabled(!marker);
  background_row_->setEnabled(!marker && bg_mode_->currentIndex() == kBgImage);
  bg_frames_->setEnabled(!marker && bg_mode_->currentIndex() == kBgFrames);
  arm_length_row_->setEnabled(kind == EngineKind::kBgsub);
  reference_row_->setEnabled(marker);
  start_->setEnabled(!marker);
  shoulder_box_->setEnabled(!marker);
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
  for (const ParamEditor& p : params_) {
    const double shown = editorValue(p);
    // A double the spin box rounded for display keeps its exact value (1/6 shows as 0.167)
    // until the operator changes it, so the GUI and the CLI analyse with the same number.
    if (p.kind == OptionKind::kDouble) {
      const double scale = std::pow(10.0, p.decimals);
      if (std::round(p.get(base_.engine) * scale) == std::round(shown * scale)) continue;
    }
    p.set(o.engine, shown);
  }
  const bool marker = o.engine.kind == EngineKind::kMarker;
  if (marker) {
    o.reference_path = reference_->text().toStdString();
    return o;
  }
  if (bg_mode_->currentIndex() == kBgImage) o.background_path = background_->text().toStdString();
  if (bg_mode_->currentIndex() == kBgFrames) {
    // As the CLI does: --background-frames K is also the bgsub background length.
    o.background_frames = bg_frames_->value();
    o.engine.bgsub.background_frames = o.background_frames;
  }
  if (o.engine.kind == EngineKind::kBgsub) o.arm_length_path = arm_length_->text().toStdString();
  o.start = start_->value();
  if (shoulder_box_->isChecked()) {
    o.shoulder_px = cv::Point2d(shoulder_x_->value(), shoulder_y_->value());
  }
  if (roi_box_->isChecked()) {
    o.roi = cv::Rect(roi_[0]->value(), roi_[1]->value(), roi_[2]->value(), roi_[3]->value());
  }
  return o;
}

void EngineSettingsPanel::setOptions(const AnalysisOptions& o) {
  base_ = o;
  engine_->setCurrentIndex(engine_->findData(int(o.engine.kind)));
  for (const ParamEditor& p : params_) setEditorValue(p, p.get(o.engine));
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
  for (const ParamEditor& p : params_) {
    const QString key = QString("%1/%2").arg(EngineName(p.engine), QString::fromStdString(p.key));
    const double v = p.get(o.engine);
    switch (p.kind) {
      case OptionKind::kInt:
        s.setValue(key, int(std::lround(v)));
        break;
      case OptionKind::kDouble:
        s.setValue(key, v);
        break;
      case OptionKind::kBool:
        s.setValue(key, v != 0);
        break;
      case OptionKind::kEnum:
        s.setValue(key, QString::fromStdString(p.choices[int(v)]));
        break;
    }
  }
  s.endGroup();
}

void EngineSettingsPanel::load(QSettings& s) {
  s.beginGroup("analysis");
  AnalysisOptions o;
  o.engine.kind =
      static_cast<EngineKind>(std::clamp(s.value("engine", int(EngineKind::kBgsub)).toInt(), 0, 2));
  for (const ParamEditor& p : params_) {
    const QString key = QString("%1/%2").arg(EngineName(p.engine), QString::fromStdString(p.key));
    if (!s.contains(key)) continue;
    const QVariant value = s.value(key);
    double v = 0;
    bool ok = true;
    if (p.kind == OptionKind::kBool) {
      v = value.toBool() ? 1 : 0;
    } else if (p.kind == OptionKind::kEnum) {
      const auto it = std::find(p.choices.begin(), p.choices.end(), value.toString().toStdString());
      ok = it != p.choices.end();
      v = double(it - p.choices.begin());
    } else {
      v = value.toDouble(&ok);
    }
    // A hand-edited or outdated settings file cannot put a parameter out of its range.
    if (ok) p.set(o.engine, std::clamp(v, p.min, p.max));
  }
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
