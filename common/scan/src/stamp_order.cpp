#include "scanfilter/stamp_order.hpp"

#include <spdlog/spdlog.h>

namespace scanfilter {

void StampOrder::check(Stamp stamp, std::size_t line) {
  if (have_last_ && stamp < last_ && regressions_++ == 0 && warn_)
    spdlog::warn("{}:{}: {} {} is earlier than the previous scan's {}; kept in file order "
                 "(further regressions are counted, not logged)",
                 path_, line, what_, stamp.toDecimal(), last_.toDecimal());
  // The filter's settings in seconds (frame_lifetime, the surface memory's
  // lifetimes) then see no time pass between the two: say so once.
  if (have_last_ && stamp == last_ && repeats_++ == 0 && warn_)
    spdlog::warn("{}:{}: {} {} equals the previous scan's; settings in seconds (frame_lifetime, the surface "
                 "memory's lifetimes) cannot tell such scans apart (further repeats are counted, not logged)",
                 path_, line, what_, stamp.toDecimal());
  last_ = stamp;
  have_last_ = true;
}

}  // namespace scanfilter
