#include "scanfilter/stamp_order.hpp"

#include <spdlog/spdlog.h>

namespace scanfilter {

void StampOrder::check(Stamp stamp, std::size_t line) {
  if (have_last_ && stamp < last_ && regressions_++ == 0)
    spdlog::warn("{}:{}: {} {} is earlier than the previous scan's {}; kept in file order "
                 "(further regressions are counted, not logged)",
                 path_, line, what_, stamp.toDecimal(), last_.toDecimal());
  last_ = stamp;
  have_last_ = true;
}

}  // namespace scanfilter
