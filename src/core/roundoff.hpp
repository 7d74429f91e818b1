// roundoff.hpp - the unit roundoff of IEEE-754 double arithmetic, defined once.
//
// Every floating-point error bound in the library (the predicates' filters,
// the free-area pipeline's vertex errors, the verifier's float filter) is a
// small multiple of this u = 2^-53: with round-to-nearest, each basic
// operation's result is the exact result times (1 + d), |d| <= u.
#ifndef PDS_ROUNDOFF_HPP
#define PDS_ROUNDOFF_HPP

namespace pds {

constexpr double kUnitRoundoff = 0x1.0p-53;

}  // namespace pds

#endif
