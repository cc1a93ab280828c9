#pragma once
// Writes an Exodus II results file in Peridigm's layout: every point is a one-node SPHERE
// element in its block; node and element ids are the point ids + 1; vectors are written as
// NameX/NameY/NameZ nodal variables (NameX/NameY in a 2D file), scalars as element variables,
// globals as global variables.
// Serial (rank 0 owns it), but it never needs a whole field: the mesh and every variable are
// written in pieces of consecutive output positions (the Exodus "partial" calls), so the caller
// can hand over one rank's range at a time.
#include <memory>
#include <string>
#include <vector>

namespace peridot {

// What the file holds, without the per-point data: O(blocks + sets + variables).
struct ExodusHeader {
  int dimension = 3;  // num_dim: 2 writes x and y only (a planar run)
  long long numPoints = 0;
  std::vector<int> blockIds;  // in output order (positions are grouped by block)
  std::vector<std::string> blockNames;
  std::vector<long long> blockCounts;
  std::vector<std::string> setNames;
  std::vector<long long> setSizes;
  std::vector<std::string> nodalNames, elementNames, globalNames;
};

class ExodusWriter {
 public:
  // Creates (clobbers) the file and defines everything in it.
  ExodusWriter(const std::string& fileName, const ExodusHeader& header);
  // Continues an existing file made by a run like this one: keeps the records whose time is
  // <= `time`, and the next record written goes right after them. Returns nullptr, with the
  // reason in `whyNot`, when the file cannot be opened or does not match `header`.
  static std::unique_ptr<ExodusWriter> resume(const std::string& fileName,
                                              const ExodusHeader& header, double time,
                                              std::string& whyNot);
  ~ExodusWriter();
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  // Mesh pieces: positions [first, first + count): ids (point id + 1) and reference
  // coordinates (3 per point, interleaved); block connectivity follows from the positions.
  void putMesh(long long first, long long count, const long long* ids, const double* xyz);
  // Node set `set` (index in header.setNames), entries [offset, offset + count): 0-based output
  // positions.
  void putSet(int set, long long offset, long long count, const long long* positions);
  // A record: begin (time and globals), the nodal / element pieces, end (flushes to disk, so
  // that a run that stops early leaves a readable file).
  void beginRecord(double time, const std::vector<double>& globals);
  void putNodal(int variable, long long first, long long count, const double* values);
  void putElement(int variable, long long first, long long count, const double* values);
  void endRecord();
  int recordsWritten() const { return step_; }
  const std::string& fileName() const { return fileName_; }

 private:
  ExodusWriter() = default;
  void check(int status, const std::string& what) const;
  std::string fileName_;
  int dimension_ = 3;
  int exoid_ = -1;
  int step_ = 0;
  std::vector<int> blockIds_;
  std::vector<long long> blockFirst_;  // first output position of each block, plus the end
};

// The last Exodus library error message, with the OS reason when errno is set ("" if none).
std::string exodusReason();

}  // namespace peridot
