// dart_stage.cpp - the dart stages, compiled once (see dart_stage.hpp).
#include "darts/dart_stage.hpp"

namespace pds {

template class DartStageOf<DartGrid<DenseCells>>;
template class DartStageOf<DartGrid<SparseCells>>;
template class DartStageOf<LayeredGrid>;

}  // namespace pds
