// An engine's parameter form, built from its option table: one editor per row, basic and
// advanced groups, defaults and saved settings.
// Length: the constructor builds one editor per table row in one loop whose cases share the
// layouts.
#include "parameter_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace armmimic::gui {
namespace {

// A long form scrolls: the wheel turns a value only in the editor that has the focus (a click or
// Tab); over any other editor it scrolls the form, so scrolling never changes a parameter.
template <typename Base>
class FocusWheel : public Base {
 public:
  using Base::Base;

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (this->hasFocus()) {
      Base::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

}  // namespace

ParameterForm::ParameterForm(EngineKind engine, std::vector<OptionField<EngineOptions>> rows,
                             QWidget* parent)
    : QWidget(parent),
      engine_(EngineName(engine)),
      advanced_toggle_(new QToolButton),
      reset_button_(new QToolButton) {
  auto* v = new QVBoxLayout(this);
  v->setContentsMargins(0, 0, 0, 0);
  auto* main_form = new QFormLayout;
  auto* advanced = new QWidget;
  advanced->setObjectName(engine_ + "Advanced");
  auto* advanced_form = new QFormLayout(advanced);
  advanced_form->setContentsMargins(12, 0, 0, 0);
  advanced_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  int advanced_count = 0;
  for (OptionField<EngineOptions>& f : rows) {
    if (f.group == OptionGroup::kInput) continue;
    const QString label = QString::fromStdString(f.label);
    QString tip = QString::fromStdString(f.help);
    QWidget* editor = nullptr;
    switch (f.kind) {
      case OptionKind::kInt: {
        auto* spin = new FocusWheel<QSpinBox>;
        spin->setRange(int(f.min), int(f.max));
        spin->setSingleStep(int(f.step));
        connect(spin, &QSpinBox::valueChanged, this, &ParameterForm::changed);
        editor = spin;
        tip += tr("\nDefault %1, range %2 to %3").arg(f.default_value).arg(f.min).arg(f.max);
        break;
      }
      case OptionKind::kDouble: {
        auto* spin = new FocusWheel<QDoubleSpinBox>;
        spin->setDecimals(f.decimals);
        spin->setRange(f.min, f.max);
        spin->setSingleStep(f.step);
        connect(spin, &QDoubleSpinBox::valueChanged, this, &ParameterForm::changed);
        editor = spin;
        tip += tr("\nDefault %1, range %2 to %3")
                   .arg(f.default_value, 0, 'g', 6)
                   .arg(f.min)
                   .arg(f.max);
        break;
      }
      case OptionKind::kBool: {
        auto* box = new QCheckBox(label);
        connect(box, &QCheckBox::toggled, this, &ParameterForm::changed);
        editor = box;
        tip += f.default_value != 0 ? tr("\nDefault: on") : tr("\nDefault: off");
        break;
      }
      case OptionKind::kEnum: {
        auto* combo = new FocusWheel<QComboBox>;
        for (const std::string& c : f.choices) combo->addItem(QString::fromStdString(c));
        connect(combo, &QComboBox::currentIndexChanged, this, &ParameterForm::changed);
        editor = combo;
        tip += tr("\nDefault: %1").arg(QString::fromStdString(f.choices[int(f.default_value)]));
        break;
      }
      case OptionKind::kText:
        break;
    }
    if (!editor) continue;  // a text row: the engines' tables have none
    editor->setObjectName(engine_ + "." + QString::fromStdString(f.key));
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
    bound_.push_back({std::move(f), editor});
    const QSignalBlocker block(editor);
    show(bound_.back(), bound_.back().field.default_value);
  }
  advanced_toggle_->setObjectName(engine_ + "AdvancedToggle");
  advanced_toggle_->setText(tr("Advanced (%1 more)").arg(advanced_count));
  advanced_toggle_->setToolTip(tr("Every other parameter of this engine"));
  advanced_toggle_->setCheckable(true);
  advanced_toggle_->setAutoRaise(true);
  advanced_toggle_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  advanced_toggle_->setArrowType(Qt::RightArrow);
  advanced->setVisible(false);
  connect(advanced_toggle_, &QToolButton::toggled, this, [this, advanced](bool on) {
    advanced_toggle_->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    advanced->setVisible(on);
  });
  reset_button_->setObjectName(engine_ + "ResetDefaults");
  reset_button_->setText(tr("Reset to defaults"));
  reset_button_->setToolTip(tr("Every parameter of this engine back to its documented default"));
  connect(reset_button_, &QToolButton::clicked, this, &ParameterForm::resetToDefaults);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(advanced_toggle_);
  buttons->addStretch();
  buttons->addWidget(reset_button_);
  v->addLayout(main_form);
  v->addLayout(buttons);
  v->addWidget(advanced);
}

void ParameterForm::resetToDefaults() {
  for (const Bound& b : bound_) show(b, b.field.default_value);
}

double ParameterForm::shown(const Bound& b) const {
  switch (b.field.kind) {
    case OptionKind::kInt:
      return static_cast<QSpinBox*>(b.widget)->value();
    case OptionKind::kDouble:
      return static_cast<QDoubleSpinBox*>(b.widget)->value();
    case OptionKind::kBool:
      return static_cast<QCheckBox*>(b.widget)->isChecked() ? 1 : 0;
    case OptionKind::kEnum:
      return static_cast<QComboBox*>(b.widget)->currentIndex();
    case OptionKind::kText:
      break;
  }
  return 0;
}

void ParameterForm::show(const Bound& b, double value) {
  switch (b.field.kind) {
    case OptionKind::kInt:
      static_cast<QSpinBox*>(b.widget)->setValue(int(std::lround(value)));
      break;
    case OptionKind::kDouble:
      static_cast<QDoubleSpinBox*>(b.widget)->setValue(value);
      break;
    case OptionKind::kBool:
      static_cast<QCheckBox*>(b.widget)->setChecked(value != 0);
      break;
    case OptionKind::kEnum:
      static_cast<QComboBox*>(b.widget)->setCurrentIndex(int(std::lround(value)));
      break;
    case OptionKind::kText:
      break;
  }
}

QString ParameterForm::settingsKey(const Bound& b) const {
  return engine_ + "/" + QString::fromStdString(b.field.key);
}

void ParameterForm::setValues(const EngineOptions& o) {
  for (const Bound& b : bound_) show(b, b.field.get(o));
}

void ParameterForm::apply(EngineOptions* o) const {
  for (const Bound& b : bound_) {
    const double value = shown(b);
    if (b.field.kind == OptionKind::kDouble) {
      const double scale = std::pow(10.0, b.field.decimals);
      if (std::round(b.field.get(*o) * scale) == std::round(value * scale)) continue;
    }
    b.field.set(*o, value);
  }
}

QWidget* ParameterForm::editor(const QString& key) const {
  for (const Bound& b : bound_) {
    if (QString::fromStdString(b.field.key) == key) return b.widget;
  }
  return nullptr;
}

void ParameterForm::save(QSettings& s, const EngineOptions& o) const {
  for (const Bound& b : bound_) {
    const double v = b.field.get(o);
    switch (b.field.kind) {
      case OptionKind::kInt:
        s.setValue(settingsKey(b), int(std::lround(v)));
        break;
      case OptionKind::kDouble:
        s.setValue(settingsKey(b), v);
        break;
      case OptionKind::kBool:
        s.setValue(settingsKey(b), v != 0);
        break;
      case OptionKind::kEnum:
        s.setValue(settingsKey(b), QString::fromStdString(b.field.choices[int(v)]));
        break;
      case OptionKind::kText:
        break;
    }
  }
}

void ParameterForm::load(QSettings& s, EngineOptions* o) const {
  for (const Bound& b : bound_) {
    const QString key = settingsKey(b);
    if (!s.contains(key)) continue;
    const QVariant value = s.value(key);
    const std::vector<std::string>& choices = b.field.choices;
    double v = 0;
    bool ok = true;
    if (b.field.kind == OptionKind::kBool) {
      v = value.toBool() ? 1 : 0;
    } else if (b.field.kind == OptionKind::kEnum) {
      const auto it = std::find(choices.begin(), choices.end(), value.toString().toStdString());
      ok = it != choices.end();
      v = double(it - choices.begin());
    } else {
      v = value.toDouble(&ok);
    }
    // A hand-edited or outdated settings file cannot put a parameter out of its range.
    if (ok) b.field.set(*o, std::clamp(v, b.field.min, b.field.max));
  }
}

}  // namespace armmimic::gui
