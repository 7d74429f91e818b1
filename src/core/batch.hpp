// batch.hpp - how many independent memory accesses the sampler keeps in
// flight together, defined once.
//
// The sampler is bound by cache misses: each dart, tree descent and ring walk
// is a chain of dependent loads. Working on a batch of them in step lets
// their misses overlap. Every batched loop (dart throwing, the tree's
// select_many, the ring prefetches, the Jones loop's candidate queue) is
// sized by this one constant, so their fixed arrays always agree.
#ifndef PDS_BATCH_HPP
#define PDS_BATCH_HPP

#include <cstddef>

namespace pds {

constexpr std::size_t kMaxBatch = 64;

}  // namespace pds

#endif
