#pragma once

#include <cstddef>
#include <cstdint>

namespace nurbslod {

// A 64-bit key's bits mixed (the finaliser of MurmurHash3), for the open-addressing tables that
// keep points by parameter or grid cell. The standard library hashes a double byte by byte and
// an integer to itself, whose low bits then cluster in a power-of-two table.
inline std::size_t mixBits(std::uint64_t bits) {
    bits ^= bits >> 33;
    bits *= 0xff51afd7ed558ccdULL;
    bits ^= bits >> 33;
    return static_cast<std::size_t>(bits);
}

}  // namespace nurbslod
