#include "field_error.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace armmimic::gui {
namespace {

constexpr const char* kMarked = "fieldError";
constexpr const char* kOldStyle = "fieldErrorOldStyle";

// Calls `clear` once, at the first change of `field` or of an editor inside it (a group box).
void OnFirstChange(QWidget* field) {
  auto clear = [field] { ClearFieldError(field); };
  const auto once = Qt::SingleShotConnection;
  QList<QWidget*> editors = field->findChildren<QWidget*>();
  editors.prepend(field);
  for (QWidget* w : editors) {
    if (auto* e = qobject_cast<QLineEdit*>(w)) {
      QObject::connect(e, &QLineEdit::textChanged, field, clear, once);
    } else if (auto* s = qobject_cast<QSpinBox*>(w)) {
      QObject::connect(s, &QSpinBox::valueChanged, field, clear, once);
    } else if (auto* d = qobject_cast<QDoubleSpinBox*>(w)) {
      QObject::connect(d, &QDoubleSpinBox::valueChanged, field, clear, once);
    } else if (auto* c = qobject_cast<QComboBox*>(w)) {
      QObject::connect(c, &QComboBox::currentIndexChanged, field, clear, once);
    } else if (auto* g = qobject_cast<QGroupBox*>(w)) {
      QObject::connect(g, &QGroupBox::toggled, field, clear, once);
    } else if (auto* b = qobject_cast<QAbstractButton*>(w); b && b->isCheckable()) {
      QObject::connect(b, &QAbstractButton::toggled, field, clear, once);
    }
  }
}

}  // namespace

void MarkFieldError(QWidget* field) {
  if (!field) return;
  if (!HasFieldError(field)) {
    field->setProperty(kOldStyle, field->styleSheet());
    field->setProperty(kMarked, true);
    // Only this widget is framed (its object name), not the editors inside a group box.
    const QString self = field->objectName().isEmpty() ? QString(field->metaObject()->className())
                                                       : QString("#%1").arg(field->objectName());
    field->setStyleSheet(
        field->styleSheet() +
        QString("%1 { border: 2px solid #d03b2f; border-radius: 3px; }").arg(self));
    OnFirstChange(field);
  }
  field->setFocus(Qt::OtherFocusReason);
}

void ClearFieldError(QWidget* field) {
  if (!field || !HasFieldError(field)) return;
  field->setStyleSheet(field->property(kOldStyle).toString());
  field->setProperty(kMarked, false);
}

bool HasFieldError(const QWidget* field) { return field && field->property(kMarked).toBool(); }

QString FieldLabel(const QWidget* field) {
  QString text;
  if (auto* g = qobject_cast<const QGroupBox*>(field)) text = g->title();
  if (auto* b = qobject_cast<const QAbstractButton*>(field)) text = b->text();
  // The form row's label: of the field itself, or of the row widget holding it (an edit with its
  // browse button).
  for (const QWidget* w = field; text.isEmpty() && w && w->parentWidget(); w = w->parentWidget()) {
    if (auto* form = qobject_cast<QFormLayout*>(w->parentWidget()->layout())) {
      if (auto* label = qobject_cast<QLabel*>(form->labelForField(const_cast<QWidget*>(w)))) {
        text = label->text();
      }
      break;
    }
  }
  text.remove('&');
  return text.isEmpty() ? field->objectName() : text;
}

}  // namespace armmimic::gui
