#include "shortcut_guard.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QTextEdit>

namespace armmimic::gui {
namespace {

enum class KeyKind { kOther, kSpace, kNavigation, kPrintable };

KeyKind Classify(const QKeyEvent& e) {
  if (e.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) {
    return KeyKind::kOther;
  }
  switch (e.key()) {
    case Qt::Key_Space:
      return KeyKind::kSpace;
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_Home:
    case Qt::Key_End:
    case Qt::Key_PageUp:
    case Qt::Key_PageDown:
      return KeyKind::kNavigation;
    default:
      break;
  }
  const QString text = e.text();
  return !text.isEmpty() && text.at(0).isPrint() ? KeyKind::kPrintable : KeyKind::kOther;
}

class ShortcutGuard : public QObject {
 public:
  using QObject::QObject;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::ShortcutOverride && watched->isWidgetType() &&
        FocusWantsKey(static_cast<QWidget*>(watched), *static_cast<QKeyEvent*>(event))) {
      event->accept();  // the key goes to the widget as a key press, not to a shortcut
    }
    return false;
  }
};

}  // namespace

bool FocusWantsKey(const QWidget* w, const QKeyEvent& e) {
  const KeyKind kind = Classify(e);
  if (kind == KeyKind::kOther || !w || !w->isEnabled()) return false;
  // Editors, lists, tables and text take every plain key: they type, search, move or scroll.
  if (qobject_cast<const QLineEdit*>(w) || qobject_cast<const QAbstractSpinBox*>(w) ||
      qobject_cast<const QComboBox*>(w) || qobject_cast<const QAbstractItemView*>(w) ||
      qobject_cast<const QTextEdit*>(w) || qobject_cast<const QPlainTextEdit*>(w)) {
    return true;
  }
  // A slider (the scrub bar) and the tabs move with the arrows, Home and End.
  if (qobject_cast<const QAbstractSlider*>(w) || qobject_cast<const QTabBar*>(w)) {
    return kind == KeyKind::kNavigation;
  }
  // A button or checkbox is pressed with Space; the arrows move between radio buttons.
  if (auto* b = qobject_cast<const QAbstractButton*>(w)) {
    return kind == KeyKind::kSpace || (kind == KeyKind::kNavigation && b->autoExclusive());
  }
  return false;
}

void GuardShortcuts(QWidget* window) { qApp->installEventFilter(new ShortcutGuard(window)); }

}  // namespace armmimic::gui
