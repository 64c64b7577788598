// The robot panel's fields named by the keys of the robot and serial option tables
// (armmimic/robot/option_tables.h, armmimic/serial/port_table.h): each editor of a planner,
// mapping, limits, port or send setting carries the property "optionKey" (e.g.
// "planner.cutoff_hz"), so an error about a key (Status::key()) can be shown at its field, and the
// table's help and unit complete its tooltip.
#pragma once

#include <QString>
#include <QWidget>

namespace armmimic::gui {

// Sets "optionKey" on the fields below `panel` (the robot panel with its Designer form) that edit
// a table row, adds the row's help and unit to each field's tooltip, and gives a number field
// its row's decimals and range.
void BindRobotOptionKeys(QWidget* panel);

// The field below `root` that edits the setting `key`, or nullptr when the panel offers none.
QWidget* RobotOptionField(QWidget* root, const QString& key);

}  // namespace armmimic::gui
