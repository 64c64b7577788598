#include "wheel_guard.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QWidget>

namespace armmimic::gui {
namespace {

class WheelFilter : public QObject {
 public:
  using QObject::QObject;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() != QEvent::Wheel) return false;
    auto* w = qobject_cast<QWidget*>(watched);
    if (!w || w->hasFocus()) return false;
    // Ignored, the event goes on to the parent: the scroll area scrolls.
    event->ignore();
    return true;
  }
};

}  // namespace

void GuardWheel(QWidget* root) {
  auto* filter = new WheelFilter(root);
  QList<QWidget*> editors;
  for (auto* s : root->findChildren<QAbstractSpinBox*>()) editors << s;
  for (auto* c : root->findChildren<QComboBox*>()) editors << c;
  for (QWidget* w : editors) {
    // Qt's default WheelFocus would hand the focus to the editor under the wheel first.
    if (w->focusPolicy() == Qt::WheelFocus) w->setFocusPolicy(Qt::StrongFocus);
    w->installEventFilter(filter);
  }
}

}  // namespace armmimic::gui
