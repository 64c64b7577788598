// ShortcutGuard: the window's one-key shortcuts (Space, the arrows, Home, End, the letters, [ and
// ]) act only when the widget with the focus does not use the key itself. Space presses a
// focused button or ticks a focused checkbox; the arrows move in a focused list, combo box,
// table, slider or text; letters type or search there. Everywhere else (the video, the plot, the
// toolbar) they play, step and pick tools as before. Keys with Ctrl or Alt, the function keys
// and Esc (stop) are never held back. Qt's own rule gives a window-wide shortcut priority over
// the focused widget; the guard answers the ShortcutOverride event for the widget instead.
#pragma once

#include <QKeySequence>

class QKeyEvent;
class QWidget;

namespace armmimic::gui {

// Whether `focus` uses `event`'s key itself (so no shortcut may take it).
bool FocusWantsKey(const QWidget* focus, const QKeyEvent& event);

// Installs the guard for the shortcuts of `window` (an application-wide event filter owned by
// `window`, removed with it).
void GuardShortcuts(QWidget* window);

}  // namespace armmimic::gui
