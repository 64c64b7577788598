// GuardWheel: in a panel that scrolls, the wheel turns a spin box or combo box only while that
// editor has the focus (a click or Tab). Over any other editor the wheel scrolls the panel, so
// scrolling past the engine, the start frame or the robot's filter cutoff never changes them.
#pragma once

class QWidget;

namespace armmimic::gui {

// Applies the rule to every spin box and combo box under `root` (present when called).
void GuardWheel(QWidget* root);

}  // namespace armmimic::gui
