#include "port_flags.h"

#include "armmimic/serial/port_table.h"

namespace armmimic::cli {

void AddPortFlags(ArgParser& p, serial::PortSettings* port) {
  // Each flag from its row of the port's table: flag, help and default.
  for (const OptionField<serial::PortSettings>& row : serial::PortOptionFields()) {
    const OptionField<serial::PortSettings>* f = &row;
    const std::string def = OptionDefaultText(row);
    const std::string help = row.help + (def.empty() ? "" : " (default " + def + ")");
    if (row.kind == OptionKind::kInt) {
      p.Custom(row.flag, "N", help, [f, port](const std::string& v) {
        int n = 0;
        if (!ParseIntArg(v, &n)) return "'" + v + "' is not a whole number";
        if (!OptionInRange(*f, n)) {
          return "'" + v + "' is out of range [" + OptionValueText(*f, f->min) + ", " +
                 OptionValueText(*f, f->max) + "]";
        }
        f->set(*port, n);
        return std::string();
      });
    } else if (row.kind == OptionKind::kEnum) {  // flow control, with its aliases
      p.Custom(row.flag, "MODE", help,
               [port](const std::string& v) { return serial::ParseFlowControl(v, &port->flow); });
    } else {
      p.Custom(row.flag, row.key == "port" ? "DEVICE" : "P", help,
               [f, port](const std::string& v) { return f->parse(v, port); });
    }
  }
}

}  // namespace armmimic::cli
