#pragma once
// A streaming parser of Gmsh's .msh files, formats 2.2 and 4.1, ASCII and binary. It never holds
// more than one element's or one entity's record: the caller receives nodes and elements one at
// a time through callbacks and keeps what it needs, so a rank can read the whole file and keep
// its share in O(share) memory. Every count is checked against the bytes left in the file before
// it drives a loop or an allocation, every read is bounded, and every problem is an InputError
// naming the deck path, the file and the line (ASCII) or byte offset (binary) where it was found.
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace peridot {

// Gmsh element types the parser knows (the others are refused with their number).
struct GmshElementType {
  int dimension = -1;  // 0 point, 1 line, 2 surface, 3 volume
  int numNodes = 0;
  int numCorners = 0;  // the first numCorners nodes are the corners (Gmsh's node order)
  const char* name = "";
};
// dimension -1 when the type is unknown.
GmshElementType gmshElementType(int type);

struct GmshElement {
  long long tag = 0;
  int type = 0;
  GmshElementType info;
  int entityTag = 0;
  // The physical groups of the element (Gmsh 2.2: the first tag when not 0; 4.1: those of its
  // entity in $Entities), in file order.
  const std::vector<int>* physicals = nullptr;
  const long long* nodes = nullptr;  // info.numNodes node tags
};

struct GmshHeader {
  std::string version;  // "2.2" or "4.1"
  bool binary = false;
  std::map<std::pair<int, int>, std::string> physicalNames;  // (dimension, tag) -> name
};

class GmshParser {
 public:
  // deckPath and fileName are for messages.
  GmshParser(std::string fileName, std::string deckPath);
  // Reads the whole file once, calling node(tag, xyz) for every node when `node` is set and
  // element(e) for every element when `element` is set. Throws InputError on any problem.
  GmshHeader parse(const std::function<void(long long, const double*)>& node,
                   const std::function<void(const GmshElement&)>& element) const;
  // "Gmsh mesh \"<file>\"" for messages that do not come from the parser.
  std::string label() const;

 private:
  std::string fileName_, deckPath_;
};

}  // namespace peridot
