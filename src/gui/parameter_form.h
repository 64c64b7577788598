// ParameterForm: one engine's parameters as a form, built from the engine's parameter table
// (armmimic/engines/option_fields.h; text rows are not shown): the main rows, then a folded
// "Advanced" section with every other field. It reads and writes the EngineOptions struct the CLI
// fills, and saves the same fields in QSettings.
#pragma once

#include <QWidget>
#include <functional>
#include <string>
#include <vector>

#include "armmimic/engines/engine_options.h"
#include "armmimic/engines/option_fields.h"

class QSettings;
class QToolButton;

namespace armmimic::gui {

// An engine's table with its accessors lifted from the engine's struct to EngineOptions.
template <typename O>
std::vector<OptionField<EngineOptions>> LiftOptionFields(const std::vector<OptionField<O>>& fields,
                                                         O EngineOptions::*member) {
  std::vector<OptionField<EngineOptions>> rows;
  for (const OptionField<O>& f : fields) {
    OptionField<EngineOptions> e;
    e.key = f.key;
    e.label = f.label;
    e.help = f.help;
    e.unit = f.unit;
    e.flag = f.flag;
    e.kind = f.kind;
    e.group = f.group;
    e.min = f.min;
    e.max = f.max;
    e.min_exclusive = f.min_exclusive;
    e.default_value = f.default_value;
    e.decimals = f.decimals;
    e.step = f.step;
    e.below = f.below;
    e.strictly_below = f.strictly_below;
    e.choices = f.choices;
    e.get = [get = f.get, member](const EngineOptions& o) { return get(o.*member); };
    e.set = [set = f.set, member](EngineOptions& o, double v) { set(o.*member, v); };
    rows.push_back(std::move(e));
  }
  return rows;
}

class ParameterForm : public QWidget {
  Q_OBJECT
 public:
  // `engine` names the widgets ("lk.max_corners") and the settings keys ("lk/max_corners").
  // Rows of OptionGroup::kInput are left out: the analysis inputs set them.
  ParameterForm(EngineKind engine, std::vector<OptionField<EngineOptions>> rows,
                QWidget* parent = nullptr);

  // Shows the values of `o`.
  void setValues(const EngineOptions& o);
  // Writes the shown values into `o`. A double the spin box rounds for display (1/6 shows as
  // 0.167) keeps the value `o` already has while it still shows that way, so the GUI analyses
  // with exactly the number the CLI would.
  void apply(EngineOptions* o) const;

  void save(QSettings& settings, const EngineOptions& o) const;
  // Reads the saved fields into `o`; a value out of its range is clamped, an unreadable one is
  // skipped.
  void load(QSettings& settings, EngineOptions* o) const;

  QWidget* editor(const QString& key) const;
  QToolButton* advancedToggle() const { return advanced_toggle_; }
  QToolButton* resetButton() const { return reset_button_; }

 public slots:
  // Every parameter of the form back to its documented default.
  void resetToDefaults();

 signals:
  void changed();

 private:
  struct Bound {
    OptionField<EngineOptions> field;
    QWidget* widget;
  };
  double shown(const Bound& b) const;
  void show(const Bound& b, double value);
  QString settingsKey(const Bound& b) const;

  QString engine_;
  std::vector<Bound> bound_;
  QToolButton* advanced_toggle_;
  QToolButton* reset_button_;
};

}  // namespace armmimic::gui
