#pragma once
// The Exodus mesh reader: each rank of a communicator reads its contiguous share of the elements
// (in file element order, across blocks) with the library's partial reads, and gets the
// coordinates and node-set memberships of its elements' nodes from the ranks that read those
// nodes. No rank holds more than O(elements / ranks + nodes / ranks) of the mesh at any time,
// plus the O(blocks + sets) metadata every rank reads.
//
// The cloud, the checks and the messages are those documented for readExodusMesh
// (ExodusMeshReader.hpp), which is this reader on MPI_COMM_SELF: the union of the shares over
// the ranks is, point for point and bit for bit, the whole cloud of a one-rank read.
#include <mpi.h>

#include <string>

#include "discretization/PointCloud.hpp"

namespace peridot {

// Collective over comm. Every problem throws InputError on every rank with the message the serial
// read reports, and when a file has several problems, the one the serial read meets first (file
// order: header, coordinates, element ids, then block by block, then node set by node set).
PointCloud readExodusMeshShare(const std::string& fileName, const std::string& deckPath,
                               double thickness, MPI_Comm comm);

}  // namespace peridot
