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
  pages_->addWidget(makeBgsubPage());
  pages_->addWidget(makeLkPage());
  pages_->addWidget(makeMarkerPage());
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
  sl->addWidget(shoulder_x_);
  sl->addWidget(new QLabel("y"));
  sl->addWidget(shoulder_y_);
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
    rl->addWidget(roi_[i]);
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

QWidget* EngineSettingsPanel::makeBgsubPage() {
  const BgsubOptions d;
  auto* w = new QWidget;
  auto* f = new QFormLayout(w);
  threshold_ =
      Spin(1, 255, d.threshold, tr("--threshold: grey-level difference (5.2.2)"), "threshold");
  bg_standstill_ =
      Spin(1, 100000, d.standstill_frames,
           tr("--standstill-frames: frames averaged into the standstill image"), "bgsubStandstill");
  straight_ratio_ = DSpin(0.01, 1.0, d.straight_ratio, 2,
                          tr("defect depth below this share of the semi-major axis: straight arm"),
                          "straightRatio");
  closing_ = Spin(1, 51, d.closing_size, tr("morphological closing kernel, pixels"), "closing");
  bg_thesis_ = new QCheckBox(tr("Thesis path only"));
  bg_thesis_->setObjectName("bgsubThesis");
  f->addRow(tr("Threshold"), threshold_);
  f->addRow(tr("Standstill frames"), bg_standstill_);
  f->addRow(tr("Straight-arm ratio"), straight_ratio_);
  f->addRow(tr("Closing size"), closing_);
  f->addRow(bg_thesis_);
  return w;
}

QWidget* EngineSettingsPanel::makeLkPage() {
  const LkOptions d;
  auto* w = new QWidget;
  auto* f = new QFormLayout(w);
  lk_standstill_ = Spin(1, 100000, d.standstill_frames,
                        tr("--standstill-frames: used to locate the shoulder"), "lkStandstill");
  initial_upper_ =
      DSpin(-180, 180, d.initial_upper_deg, 1, tr("--initial-upper, degrees"), "initialUpper");
  initial_fore_ =
      DSpin(-180, 180, d.initial_fore_deg, 1, tr("--initial-fore, degrees"), "initialFore");
  still_drop_ = Spin(1, 100000, d.still_frames_drop,
                     tr("a feature still for more than this many frames is dropped"), "stillDrop");
  lk_thesis_ = new QCheckBox(tr("Thesis path only"));
  lk_thesis_->setObjectName("lkThesis");
  f->addRow(tr("Standstill frames"), lk_standstill_);
  f->addRow(tr("Initial upper arm"), initial_upper_);
  f->addRow(tr("Initial forearm"), initial_fore_);
  f->addRow(tr("Drop still features after"), still_drop_);
  f->addRow(lk_thesis_);
  return w;
}

QWidget* EngineSettingsPanel::makeMarkerPage() {
  const MarkerOptions d;
  auto* w = new QWidget;
  auto* f = new QFormLayout(w);
  median_ = Spin(1, 31, d.median_size, tr("median filter window (odd)"), "median");
  median_->setSingleStep(2);
  low_ = Spin(0, 255, d.low, tr("--low: darkest marker grey level"), "markerLow");
  high_ = Spin(0, 255, d.high, tr("--high: brightest marker grey level"), "markerHigh");
  flood_ = Spin(0, 255, d.flood_range, tr("flood-fill value range (+/-)"), "floodRange");
  marker_thesis_ = new QCheckBox(tr("Thesis path only"));
  marker_thesis_->setObjectName("markerThesis");
  f->addRow(tr("Median window"), median_);
  f->addRow(tr("Low threshold"), low_);
  f->addRow(tr("High threshold"), high_);
  f->addRow(tr("Flood range"), flood_);
  f->addRow(marker_thesis_);
  return w;
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
  o.engine.bgsub.threshold = threshold_->value();
  o.engine.bgsub.standstill_frames = bg_standstill_->value();
  o.engine.bgsub.straight_ratio = straight_ratio_->value();
  o.engine.bgsub.closing_size = closing_->value();
  o.engine.bgsub.thesis_mode = bg_thesis_->isChecked();
  o.engine.lk.standstill_frames = lk_standstill_->value();
  o.engine.lk.initial_upper_deg = initial_upper_->value();
  o.engine.lk.initial_fore_deg = initial_fore_->value();
  o.engine.lk.still_frames_drop = still_drop_->value();
  o.engine.lk.thesis_mode = lk_thesis_->isChecked();
  o.engine.marker.median_size = median_->value();
  o.engine.marker.low = low_->value();
  o.engine.marker.high = high_->value();
  o.engine.marker.flood_range = flood_->value();
  o.engine.marker.thesis_mode = marker_thesis_->isChecked();
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
  threshold_->setValue(o.engine.bgsub.threshold);
  bg_standstill_->setValue(o.engine.bgsub.standstill_frames);
  straight_ratio_->setValue(o.engine.bgsub.straight_ratio);
  closing_->setValue(o.engine.bgsub.closing_size);
  bg_thesis_->setChecked(o.engine.bgsub.thesis_mode);
  lk_standstill_->setValue(o.engine.lk.standstill_frames);
  initial_upper_->setValue(o.engine.lk.initial_upper_deg);
  initial_fore_->setValue(o.engine.lk.initial_fore_deg);
  still_drop_->setValue(o.engine.lk.still_frames_drop);
  lk_thesis_->setChecked(o.engine.lk.thesis_mode);
  median_->setValue(o.engine.marker.median_size);
  low_->setValue(o.engine.marker.low);
  high_->setValue(o.engine.marker.high);
  flood_->setValue(o.engine.marker.flood_range);
  marker_thesis_->setChecked(o.engine.marker.thesis_mode);
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
  s.setValue("bgsub/threshold", o.engine.bgsub.threshold);
  s.setValue("bgsub/standstill", o.engine.bgsub.standstill_frames);
  s.setValue("bgsub/straightRatio", o.engine.bgsub.straight_ratio);
  s.setValue("bgsub/closing", o.engine.bgsub.closing_size);
  s.setValue("bgsub/thesis", o.engine.bgsub.thesis_mode);
  s.setValue("lk/standstill", o.engine.lk.standstill_frames);
  s.setValue("lk/initialUpper", o.engine.lk.initial_upper_deg);
  s.setValue("lk/initialFore", o.engine.lk.initial_fore_deg);
  s.setValue("lk/stillDrop", o.engine.lk.still_frames_drop);
  s.setValue("lk/thesis", o.engine.lk.thesis_mode);
  s.setValue("marker/median", o.engine.marker.median_size);
  s.setValue("marker/low", o.engine.marker.low);
  s.setValue("marker/high", o.engine.marker.high);
  s.setValue("marker/flood", o.engine.marker.flood_range);
  s.setValue("marker/thesis", o.engine.marker.thesis_mode);
  s.endGroup();
}

void EngineSettingsPanel::load(QSettings& s) {
  s.beginGroup("analysis");
  AnalysisOptions o;
  o.engine.kind =
      static_cast<EngineKind>(std::clamp(s.value("engine", int(EngineKind::kBgsub)).toInt(), 0, 2));
  o.engine.bgsub.threshold = s.value("bgsub/threshold", o.engine.bgsub.threshold).toInt();
  o.engine.bgsub.standstill_frames =
      s.value("bgsub/standstill", o.engine.bgsub.standstill_frames).toInt();
  o.engine.bgsub.straight_ratio =
      s.value("bgsub/straightRatio", o.engine.bgsub.straight_ratio).toDouble();
  o.engine.bgsub.closing_size = s.value("bgsub/closing", o.engine.bgsub.closing_size).toInt();
  o.engine.bgsub.thesis_mode = s.value("bgsub/thesis", false).toBool();
  o.engine.lk.standstill_frames = s.value("lk/standstill", o.engine.lk.standstill_frames).toInt();
  o.engine.lk.initial_upper_deg =
      s.value("lk/initialUpper", o.engine.lk.initial_upper_deg).toDouble();
  o.engine.lk.initial_fore_deg = s.value("lk/initialFore", o.engine.lk.initial_fore_deg).toDouble();
  o.engine.lk.still_frames_drop = s.value("lk/stillDrop", o.engine.lk.still_frames_drop).toInt();
  o.engine.lk.thesis_mode = s.value("lk/thesis", false).toBool();
  o.engine.marker.median_size = s.value("marker/median", o.engine.marker.median_size).toInt();
  o.engine.marker.low = s.value("marker/low", o.engine.marker.low).toInt();
  o.engine.marker.high = s.value("marker/high", o.engine.marker.high).toInt();
  o.engine.marker.flood_range = s.value("marker/flood", o.engine.marker.flood_range).toInt();
  o.engine.marker.thesis_mode = s.value("marker/thesis", false).toBool();
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
