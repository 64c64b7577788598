// BgsubOptions::Check(): the ranges of the bgsub table (option_table.cpp), nothing else.
#include "armmimic/engines/bgsub_options.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {

Status BgsubOptions::Check() const {
  return CheckOptionFields(BgsubOptionFields(), "bgsub", *this);
}

}  // namespace armmimic
