#include "discretization/GmshParser.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "core/Error.hpp"

namespace peridot {

GmshElementType gmshElementType(int type) {
  switch (type) {
    case 1:
      return {1, 2, 2, "2-node line"};
    case 2:
      return {2, 3, 3, "3-node triangle"};
    case 3:
      return {2, 4, 4, "4-node quadrangle"};
    case 4:
      return {3, 4, 4, "4-node tetrahedron"};
    case 5:
      return {3, 8, 8, "8-node hexahedron"};
    case 6:
      return {3, 6, 6, "6-node prism"};
    case 7:
      return {3, 5, 5, "5-node pyramid"};
    case 8:
      return {1, 3, 2, "3-node line"};
    case 9:
      return {2, 6, 3, "6-node triangle"};
    case 10:
      return {2, 9, 4, "9-node quadrangle"};
    case 11:
      return {3, 10, 4, "10-node tetrahedron"};
    case 12:
      return {3, 27, 8, "27-node hexahedron"};
    case 13:
      return {3, 18, 6, "18-node prism"};
    case 14:
      return {3, 14, 5, "14-node pyramid"};
    case 15:
      return {0, 1, 1, "point"};
    case 16:
      return {2, 8, 4, "8-node quadrangle"};
    case 17:
      return {3, 20, 8, "20-node hexahedron"};
    case 18:
      return {3, 15, 6, "15-node prism"};
    case 19:
      return {3, 13, 5, "13-node pyramid"};
    default:
      return {};
  }
}

namespace {

// A word from the file as it may appear in a message: non-printable bytes as \xHH, cut at 40.
std::string printable(const std::string& word) {
  std::string out;
  for (std::size_t i = 0; i < word.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(word[i]);
    if (c >= 32 && c < 127) {
      out.push_back(static_cast<char>(c));
    } else {
      const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  return word.size() > 40 ? out + "..." : out;
}

// A byte reader over the file that knows its offset and (for text) its line, so that every
// message can say where the problem is. All reads stop at the end of the file with an error.
class Cursor {
 public:
  Cursor(const std::string& fileName, std::string label)
      : in_(fileName, std::ios::binary), label_(std::move(label)) {
    if (!in_) fail("cannot be opened: " + std::string(std::strerror(errno)));
    in_.seekg(0, std::ios::end);
    size_ = static_cast<long long>(in_.tellg());
    in_.seekg(0);
  }

  bool binary = false;  // messages give byte offsets instead of lines once the file is binary

  long long offset() const { return offset_; }
  long long line() const { return line_; }
  long long left() const { return size_ - offset_; }
  void seek(long long offset, long long line) {
    in_.clear();
    in_.seekg(offset);
    offset_ = offset;
    line_ = line;
  }

  [[noreturn]] void fail(const std::string& message) const {
    std::string where =
        binary ? "byte offset " + std::to_string(offset_) : "line " + std::to_string(line_);
    throw InputError("", label_ + " " + where + ": " + message);
  }

  int get() {
    const int c = in_.get();
    if (c == EOF) return EOF;
    ++offset_;
    if (c == '\n') ++line_;
    return c;
  }
  int peek() { return in_.peek(); }

  void skipSpace() {
    while (true) {
      const int c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        get();
      } else {
        return;
      }
    }
  }

  // A whitespace-separated word of at most maxLength characters.
  std::string token(const char* what, std::size_t maxLength = 64) {
    skipSpace();
    std::string word;
    while (true) {
      const int c = peek();
      if (c == EOF || c == ' ' || c == '\t' || c == '\r' || c == '\n') break;
      if (word.size() >= maxLength) fail("expected " + std::string(what) + ", found a long word");
      if (c == 0) fail("expected " + std::string(what) + ", found a NUL byte");
      word.push_back(static_cast<char>(get()));
    }
    if (word.empty()) fail("expected " + std::string(what) + ", found the end of the file");
    return word;
  }

  long long integer(const char* what, long long lo, long long hi) {
    const std::string word = token(what);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(word.c_str(), &end, 10);
    if (end != word.c_str() + word.size() || errno == ERANGE) {
      fail("expected " + std::string(what) + " (an integer), found \"" + printable(word) + "\"");
    }
    return checkRange(v, what, lo, hi);
  }

  double real(const char* what) {
    const std::string word = token(what);
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size()) {
      fail("expected " + std::string(what) + " (a number), found \"" + printable(word) + "\"");
    }
    return checkFinite(v, what);
  }

  long long checkRange(long long v, const char* what, long long lo, long long hi) const {
    if (v < lo || v > hi) {
      fail(std::string(what) + " is " + std::to_string(v) + ", outside " + std::to_string(lo) +
           ".." + std::to_string(hi));
    }
    return v;
  }
  double checkFinite(double v, const char* what) const {
    if (!std::isfinite(v)) fail(std::string(what) + " is not a finite number");
    return v;
  }

  // Consumes the rest of the current line (only blanks allowed) and its newline.
  void endLine() {
    while (true) {
      const int c = get();
      if (c == '\n') return;
      if (c == EOF) fail("unexpected end of the file");
      if (c != ' ' && c != '\t' && c != '\r') fail("unexpected data at the end of a line");
    }
  }

  void bytes(void* out, std::size_t n, const char* what) {
    if (static_cast<long long>(n) > left()) {
      fail("the file ends inside " + std::string(what) + " (truncated?)");
    }
    in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
    if (in_.gcount() != static_cast<std::streamsize>(n)) fail("read error in " + std::string(what));
    offset_ += static_cast<long long>(n);
  }
  int32_t int32(const char* what) {
    int32_t v;
    bytes(&v, sizeof v, what);
    return v;
  }
  // A size_t of the 4.1 binary format (8 bytes), as a count or tag bounded by [lo, hi].
  long long size64(const char* what, long long lo, long long hi) {
    uint64_t v;
    bytes(&v, sizeof v, what);
    if (v > static_cast<uint64_t>(LLONG_MAX)) {
      fail(std::string(what) + " is " + std::to_string(v) + ", outside " + std::to_string(lo) +
           ".." + std::to_string(hi));
    }
    return checkRange(static_cast<long long>(v), what, lo, hi);
  }
  double float64(const char* what) {
    double v;
    bytes(&v, sizeof v, what);
    return checkFinite(v, what);
  }

  // A count of items that each take at least minBytes bytes in the rest of the file.
  long long count(long long v, long long minBytes, const char* what) const {
    if (v < 0 || v > left() / std::max<long long>(minBytes, 1)) {
      fail(std::string(what) + " is " + std::to_string(v) + ", more than the " +
           std::to_string(left()) + " bytes left in the file can hold (truncated or corrupt?)");
    }
    return v;
  }

 private:
  std::ifstream in_;
  std::string label_;
  long long size_ = 0, offset_ = 0, line_ = 1;
};

const long long kMaxTag = (1LL << 62);

struct Parse {
  Cursor& c;
  Cursor& second;  // a second reader, for 4.1 node blocks (tags first, coordinates after)
  const std::function<void(long long, const double*)>& node;
  const std::function<void(const GmshElement&)>& element;
  GmshHeader header;
  std::map<std::pair<int, int>, std::vector<int>> entityPhysicals;  // 4.1: (dim, tag) -> groups
  bool sawFormat = false, sawNodes = false, sawElements = false, sawEntities = false;
  long long numElements = 0;

  bool v4() const { return header.version == "4.1"; }
  bool bin() const { return header.binary; }

  // Counts and small integers: text or the binary width of the format.
  long long count(const char* what, long long minBytes) {
    const long long v = bin() ? (v4() ? c.size64(what, 0, LLONG_MAX) : c.int32(what))
                              : c.integer(what, 0, LLONG_MAX);
    return c.count(v, minBytes, what);
  }
  int int32Field(const char* what, long long lo, long long hi) {
    return static_cast<int>(bin() ? c.checkRange(c.int32(what), what, lo, hi)
                                  : c.integer(what, lo, hi));
  }
  long long tagField(const char* what) {  // 4.1: size_t in binary
    return bin() ? c.size64(what, 1, kMaxTag) : c.integer(what, 1, kMaxTag);
  }
  double realField(const char* what) { return bin() ? c.float64(what) : c.real(what); }

  void expectEnd(const std::string& section) {
    const std::string word = c.token(("$End" + section).c_str(), 64);
    if (word != "$End" + section) {
      c.fail("expected $End" + section + ", found \"" + printable(word) +
             "\" (a wrong count, or truncated)");
    }
  }

  void meshFormat() {
    header.version = c.token("the format version", 16);
    if (header.version == "4" || header.version == "4.0" || header.version == "2" ||
        header.version == "2.0" || header.version == "2.1") {
      c.fail("format " + header.version +
             " is not supported; save the mesh as format 4.1 or 2.2 (gmsh -format msh41)");
    }
    if (header.version != "4.1" && header.version != "2.2") {
      c.fail("expected format version 4.1 or 2.2, found \"" + printable(header.version) + "\"");
    }
    const long long fileType = c.integer("the file type", 0, 1);
    c.integer("the data size", 8, 8);
    header.binary = fileType == 1;
    c.endLine();
    if (header.binary) {
      c.binary = true;
      if (c.int32("the byte-order mark") != 1) {
        c.fail("the binary mesh was written on a machine of the other byte order");
      }
    }
    expectEnd("MeshFormat");
    sawFormat = true;
  }

  void physicalNames() {
    const long long n = c.integer("the number of physical names", 0, LLONG_MAX);
    c.count(n, 6, "the number of physical names");
    for (long long i = 0; i < n; ++i) {
      const int dim = static_cast<int>(c.integer("a physical group's dimension", 0, 3));
      const int tag = static_cast<int>(c.integer("a physical group's tag", 1, INT_MAX));
      c.skipSpace();
      if (c.get() != '"') c.fail("expected a quoted physical name");
      std::string name;
      while (true) {
        const int ch = c.get();
        if (ch == '"') break;
        if (ch == EOF || ch == '\n' || ch == 0) c.fail("unterminated physical name");
        if (ch < 32 || ch == 127) c.fail("a physical name holds a control character");
        if (name.size() >= 256) c.fail("a physical name is longer than 256 characters");
        name.push_back(static_cast<char>(ch));
      }
      if (name.empty()) c.fail("empty physical name");
      header.physicalNames[{dim, tag}] = name;
    }
    expectEnd("PhysicalNames");
  }

  // 4.1 $Entities: the physical groups of every point, curve, surface and volume.
  void entities() {
    long long counts[4];
    for (long long& n : counts) n = count("the number of entities", 8);
    const bool bin8 = bin();
    for (int dim = 0; dim < 4; ++dim) {
      for (long long i = 0; i < counts[dim]; ++i) {
        const int tag = bin8 ? c.int32("an entity tag")
                             : static_cast<int>(c.integer("an entity tag", 1, INT_MAX));
        if (tag < 1) c.fail("an entity tag is " + std::to_string(tag) + "; it must be positive");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) realField("an entity's bounding box");
        const long long numPhysicals = count("the number of physical groups of an entity", 1);
        std::vector<int> groups;
        for (long long k = 0; k < numPhysicals; ++k) {
          // Gmsh writes a negative tag for a group whose orientation is reversed.
          const int g = bin8 ? c.int32("a physical tag")
                             : static_cast<int>(c.integer("a physical tag", -INT_MAX, INT_MAX));
          if (g == 0) c.fail("a physical tag is 0");
          groups.push_back(std::abs(g));
        }
        if (dim > 0) {
          const long long numBounding = count("the number of bounding entities", 1);
          for (long long k = 0; k < numBounding; ++k) {
            if (bin8) {
              c.int32("a bounding entity tag");
            } else {
              c.integer("a bounding entity tag", -INT_MAX, INT_MAX);
            }
          }
        }
        if (!entityPhysicals.emplace(std::make_pair(dim, tag), std::move(groups)).second) {
          c.fail("entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) +
                 " is listed twice");
        }
      }
    }
    sawEntities = true;
    expectEnd("Entities");
  }

  // Format 2.2 writes its counts as text even in binary files; the data follows the count's line.
  long long count2(const char* what, long long minBytes) {
    const long long n = c.count(c.integer(what, 0, LLONG_MAX), minBytes, what);
    if (bin()) c.endLine();
    return n;
  }

  void nodes2() {
    const long long n = count2("the number of nodes", bin() ? 28 : 8);
    double x[3];
    for (long long i = 0; i < n; ++i) {
      const long long tag = bin() ? c.checkRange(c.int32("a node tag"), "a node tag", 1, INT_MAX)
                                  : c.integer("a node tag", 1, kMaxTag);
      for (double& v : x) v = realField("a node coordinate");
      if (node) node(tag, x);
    }
    expectEnd("Nodes");
  }

  void nodes4() {
    const long long numBlocks = count("the number of node blocks", bin() ? 20 : 8);
    const long long numNodes = count("the number of nodes", bin() ? 32 : 8);
    tagField("the smallest node tag");
    tagField("the largest node tag");
    long long total = 0;
    double x[3];
    for (long long b = 0; b < numBlocks; ++b) {
      const int dim = int32Field("a node block's entity dimension", 0, 3);
      int32Field("a node block's entity tag", 1, INT_MAX);
      const int parametric = int32Field("the parametric flag", 0, 1);
      const int extra = parametric != 0 ? dim : 0;  // u, v, w after x, y, z
      const long long n = count("the number of nodes in a block", bin() ? 8 + 8 * (3 + extra) : 8);
      total += n;
      if (total > numNodes) c.fail("the node blocks hold more nodes than the header's count");
      // The block lists its n tags, then its n coordinate records: a second reader walks the
      // tags while this one reads the coordinates, so nothing is buffered.
      const long long tagsAt = c.offset(), tagsLine = c.line();
      if (bin()) {
        c.seek(tagsAt + 8 * n, tagsLine);
      } else {
        for (long long i = 0; i < n; ++i) c.integer("a node tag", 1, kMaxTag);
      }
      second.binary = c.binary;
      second.seek(tagsAt, tagsLine);
      for (long long i = 0; i < n; ++i) {
        const long long tag = bin() ? second.size64("a node tag", 1, kMaxTag)
                                    : second.integer("a node tag", 1, kMaxTag);
        for (double& v : x) v = realField("a node coordinate");
        for (int k = 0; k < extra; ++k) realField("a parametric coordinate");
        if (node) node(tag, x);
      }
    }
    if (total != numNodes) c.fail("the node blocks hold fewer nodes than the header's count");
    expectEnd("Nodes");
  }

  GmshElementType elementType(int type) {
    const GmshElementType t = gmshElementType(type);
    if (t.dimension < 0) {
      c.fail("element type " + std::to_string(type) +
             " is not supported (supported: points, lines, triangles, quadrangles, tetrahedra, "
             "hexahedra, prisms and pyramids, first and second order)");
    }
    return t;
  }

  void elements2() {
    numElements = count2("the number of elements", 8);
    long long nodesOf[27];
    std::vector<int> physicals;
    GmshElement e;
    e.nodes = nodesOf;
    e.physicals = &physicals;
    long long done = 0;
    const auto one = [&](int type, const GmshElementType& t, int numTags, bool binary) {
      e.tag = binary ? c.checkRange(c.int32("an element tag"), "an element tag", 1, INT_MAX)
                     : c.integer("an element tag", 1, kMaxTag);
      if (!binary) {
        type = static_cast<int>(c.integer("an element type", 1, INT_MAX));
        e.info = elementType(type);
        numTags = static_cast<int>(c.integer("the number of element tags", 0, 64));
      } else {
        e.info = t;
      }
      e.type = type;
      physicals.clear();
      e.entityTag = 0;
      for (int k = 0; k < numTags; ++k) {
        const long long v = binary ? c.int32("an element tag value")
                                   : c.integer("an element tag value", INT_MIN, INT_MAX);
        if (k == 0 && v != 0) {
          if (v < 0) c.fail("a physical tag is negative");
          physicals.push_back(static_cast<int>(v));
        }
        if (k == 1) e.entityTag = static_cast<int>(v);
      }
      for (int k = 0; k < e.info.numNodes; ++k) {
        nodesOf[k] = binary ? c.checkRange(c.int32("a node tag"), "a node tag", 1, INT_MAX)
                            : c.integer("a node tag", 1, kMaxTag);
      }
      if (element) element(e);
    };
    if (!bin()) {
      for (long long i = 0; i < numElements; ++i) one(0, {}, 0, false);
    } else {
      while (done < numElements) {
        const int type = c.int32("an element type");
        const GmshElementType t = elementType(type);
        const int following = c.int32("the number of elements in a group");
        const int numTags = c.int32("the number of element tags");
        if (following < 1 || following > numElements - done) {
          c.fail("an element group of " + std::to_string(following) + " elements, but " +
                 std::to_string(numElements - done) + " are left to read");
        }
        if (numTags < 0 || numTags > 64) c.fail("the number of element tags is out of range");
        for (int i = 0; i < following; ++i) one(type, t, numTags, true);
        done += following;
      }
    }
    sawElements = true;
    expectEnd("Elements");
  }

  void elements4() {
    if (!sawEntities) c.fail("$Elements comes before $Entities (format 4.1 needs $Entities)");
    const long long numBlocks = count("the number of element blocks", bin() ? 20 : 8);
    numElements = count("the number of elements", bin() ? 16 : 4);
    tagField("the smallest element tag");
    tagField("the largest element tag");
    long long nodesOf[27];
    GmshElement e;
    e.nodes = nodesOf;
    static const std::vector<int> none;
    long long total = 0;
    for (long long b = 0; b < numBlocks; ++b) {
      const int dim = int32Field("an element block's entity dimension", 0, 3);
      e.entityTag = int32Field("an element block's entity tag", 1, INT_MAX);
      e.type = int32Field("an element type", 1, INT_MAX);
      e.info = elementType(e.type);
      if (e.info.dimension != dim) {
        c.fail("an element block of entity dimension " + std::to_string(dim) + " holds " +
               e.info.name + "s");
      }
      const auto it = entityPhysicals.find({dim, e.entityTag});
      if (it == entityPhysicals.end()) {
        c.fail("element block of entity " + std::to_string(e.entityTag) + " (dimension " +
               std::to_string(dim) + "), which $Entities does not list");
      }
      e.physicals = it->second.empty() ? &none : &it->second;
      const long long n = count("the number of elements in a block",
                                bin() ? 8 * (1 + e.info.numNodes) : 2 * (1 + e.info.numNodes));
      total += n;
      if (total > numElements)
        c.fail("the element blocks hold more elements than the header's count");
      for (long long i = 0; i < n; ++i) {
        e.tag = tagField("an element tag");
        for (int k = 0; k < e.info.numNodes; ++k) nodesOf[k] = tagField("a node tag");
        if (element) element(e);
      }
    }
    if (total != numElements)
      c.fail("the element blocks hold fewer elements than the header's count");
    sawElements = true;
    expectEnd("Elements");
  }

  // An unknown section: skipped up to its $End line (binary data cannot contain a newline
  // followed by "$End<name>" by accident often enough to matter; a wrong guess is an error).
  void skipSection(const std::string& name) {
    const std::string end = "$End" + name;
    std::size_t matched = 0;
    bool lineStart = false;
    while (true) {
      const int ch = c.get();
      if (ch == EOF) c.fail("section $" + name + " has no " + end);
      if (lineStart || matched > 0) {
        if (ch == end[matched]) {
          if (++matched == end.size()) return;
          continue;
        }
        matched = 0;
      }
      lineStart = ch == '\n';
    }
  }

  void run() {
    while (true) {
      c.skipSpace();
      if (c.peek() == EOF) break;
      const std::string word = c.token("a section name", 64);
      if (word.size() < 2 || word[0] != '$') {
        c.fail("expected a $Section, found \"" + printable(word) + "\"");
      }
      const std::string name = word.substr(1);
      if (name != "MeshFormat" && !sawFormat) c.fail("the file must begin with $MeshFormat");
      if (name == "MeshFormat") {
        if (sawFormat) c.fail("a second $MeshFormat");
        meshFormat();
        continue;
      }
      // Binary sections start right after their name's line.
      if (bin() && name != "PhysicalNames") c.endLine();
      if (name == "PhysicalNames") {
        physicalNames();
      } else if (name == "Entities" && v4()) {
        if (sawEntities) c.fail("a second $Entities");
        entities();
      } else if (name == "Nodes") {
        if (sawNodes) c.fail("a second $Nodes");
        sawNodes = true;
        v4() ? nodes4() : nodes2();
      } else if (name == "Elements") {
        if (sawElements) c.fail("a second $Elements");
        v4() ? elements4() : elements2();
      } else if (name == "PartitionedEntities" || name == "GhostElements") {
        c.fail(
            "partitioned meshes are not supported: save the whole mesh (Mesh.PartitionOldStyle"
            " off, no -part), Peridot distributes it itself");
      } else if (name.rfind("End", 0) == 0) {
        c.fail("\"" + printable(word) + "\" without its section");
      } else {
        skipSection(name);
      }
    }
    if (!sawFormat) c.fail("the file is empty or has no $MeshFormat");
    if (!sawNodes) c.fail("the file has no $Nodes section");
    if (!sawElements) c.fail("the file has no $Elements section");
  }
};

}  // namespace

GmshParser::GmshParser(std::string fileName, std::string deckPath)
    : fileName_(std::move(fileName)), deckPath_(std::move(deckPath)) {}

std::string GmshParser::label() const { return "Gmsh mesh \"" + fileName_ + "\""; }

GmshHeader GmshParser::parse(const std::function<void(long long, const double*)>& node,
                             const std::function<void(const GmshElement&)>& element) const {
  std::error_code error;
  const auto status = std::filesystem::status(fileName_, error);
  if (error || !std::filesystem::exists(status)) {
    throw InputError(deckPath_, label() +
                                    " does not exist (a relative path is taken from the "
                                    "directory peridot runs in)");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(deckPath_, label() + " is not a regular file");
  }
  try {
    Cursor cursor(fileName_, label());
    Cursor second(fileName_, label());
    Parse p{cursor, second, node, element, {}, {}};
    p.run();
    return p.header;
  } catch (const InputError& e) {
    throw InputError(deckPath_, e.what());
  }
}

}  // namespace peridot
