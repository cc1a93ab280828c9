#pragma once
// The text mesh reader (`x y z block_id volume` lines): each rank of a communicator reads a byte
// range of the file, taking the lines that start in it, so no rank holds more than its share.
#include <mpi.h>

#include <string>

#include "discretization/PointCloud.hpp"

namespace peridot {

// Collective over comm. Point ids are the index of the data line among all data lines of the
// file; '#', '/' and '*' start comment lines; blank lines are skipped. With dimension 2 every z
// must be 0 and the fifth column is the point's area, multiplied by thickness. A bad line throws
// InputError on every rank naming the first bad line of the file by its line number.
PointCloud readTextMeshShare(const std::string& fileName, const std::string& deckPath,
                             int dimension, double thickness, MPI_Comm comm);

}  // namespace peridot
