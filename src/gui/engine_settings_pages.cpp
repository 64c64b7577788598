// EngineSettingsPanel's engine entries and parameter pages: one ParameterForm per engine, built
// from its table, each on its own page. The hybrid engine runs lk and bgsub and takes their
// parameters too: while it is chosen, their forms (the same editors, so every value and saved
// setting stays in one place) sit on its page below its own.
#include <QComboBox>
#include <QGroupBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include "engine_settings_panel.h"
#include "parameter_form.h"

namespace armmimic::gui {

void EngineSettingsPanel::makeForms() {
  engine_->addItem(tr("Background subtraction (ch. 5)"), int(EngineKind::kBgsub));
  engine_->addItem(tr("Lucas–Kanade tracking (ch. 6)"), int(EngineKind::kLk));
  engine_->addItem(tr("Marker joint (ch. 4)"), int(EngineKind::kMarker));
  engine_->addItem(tr("Pose network"), int(EngineKind::kPose));
  engine_->addItem(tr("Hybrid: tracking checked by the background (lk + bgsub)"),
                   int(EngineKind::kHybrid));
  forms_[int(EngineKind::kBgsub)] = new ParameterForm(
      EngineKind::kBgsub, LiftOptionFields(BgsubOptionFields(), &EngineOptions::bgsub));
  forms_[int(EngineKind::kLk)] =
      new ParameterForm(EngineKind::kLk, LiftOptionFields(LkOptionFields(), &EngineOptions::lk));
  forms_[int(EngineKind::kMarker)] = new ParameterForm(
      EngineKind::kMarker, LiftOptionFields(MarkerOptionFields(), &EngineOptions::marker));
  forms_[int(EngineKind::kPose)] = new ParameterForm(
      EngineKind::kPose, LiftOptionFields(PoseOptionFields(), &EngineOptions::pose));
  forms_[int(EngineKind::kHybrid)] = new ParameterForm(
      EngineKind::kHybrid, LiftOptionFields(HybridOptionFields(), &EngineOptions::hybrid));
  for (int i = 0; i < kEngines; ++i) {
    own_page_[i] = new QWidget;
    auto* l = new QVBoxLayout(own_page_[i]);
    l->setContentsMargins(0, 0, 0, 0);
    l->addWidget(forms_[i]);
    pages_->addWidget(own_page_[i]);
    connect(forms_[i], &ParameterForm::changed, this, &EngineSettingsPanel::changed);
  }
  auto* hybrid = static_cast<QVBoxLayout*>(own_page_[int(EngineKind::kHybrid)]->layout());
  const QString titles[2] = {tr("Background difference, the second opinion (bgsub)"),
                             tr("Tracking (lk)")};
  for (int i : {int(EngineKind::kLk), int(EngineKind::kBgsub)}) {
    auto* box = new QGroupBox(titles[i]);
    box->setObjectName(i == int(EngineKind::kLk) ? "hybridLk" : "hybridBgsub");
    new QVBoxLayout(box);
    hybrid_part_[i] = box;
    hybrid->addWidget(box);
  }
}

void EngineSettingsPanel::placeForms(EngineKind kind) {
  for (int i : {int(EngineKind::kBgsub), int(EngineKind::kLk)}) {
    QWidget* target = kind == EngineKind::kHybrid ? hybrid_part_[i] : own_page_[i];
    ParameterForm* form = forms_[i];
    if (form->parentWidget() == target) continue;
    if (QWidget* from = form->parentWidget(); from && from->layout()) {
      from->layout()->removeWidget(form);
    }
    target->layout()->addWidget(form);
    form->setVisible(true);
  }
}

QWidget* EngineSettingsPanel::parameterEditor(EngineKind engine, const QString& key) const {
  return forms_[int(engine)]->editor(key);
}

QToolButton* EngineSettingsPanel::advancedToggle(EngineKind engine) const {
  return forms_[int(engine)]->advancedToggle();
}

QToolButton* EngineSettingsPanel::resetButton(EngineKind engine) const {
  return forms_[int(engine)]->resetButton();
}

}  // namespace armmimic::gui
