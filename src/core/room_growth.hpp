// room_growth.hpp - the one growth policy for the room reserved for points.
#pragma once

#include <algorithm>
#include <cstddef>

namespace pds {

// Room to reserve when `need` points do not fit and `held` are there: at
// least double (and a first room), so that small calls and epochs cost O(1)
// amortized, but never more than `cap` unless `need` asks for it.
inline std::size_t grown_room(std::size_t need, std::size_t held, std::size_t cap) {
    constexpr std::size_t kFirstRoom = 64;  // points reserved at the first growth, at least
    return std::max(need, std::min(2 * held + kFirstRoom, cap));
}

}  // namespace pds
