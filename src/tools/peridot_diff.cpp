// peridot-diff: compares an Exodus result file with a gold file under a .comp tolerance file (the
// SEACAS exodiff -f subset Peridigm's regression tests use).
//
//   peridot-diff [-q] FILE.comp RESULT.e GOLD.e
//
// Exit status: 0 when every compared value is within tolerance and the files match structurally,
// 1 when there are differences, 2 on a usage error or a file that cannot be read.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "output/ExodusCompare.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: peridot-diff [-q] FILE.comp RESULT.e GOLD.e\n"
         "  Compares RESULT.e with GOLD.e using the tolerances in FILE.comp (exodiff -f format).\n"
         "  -q  print only problems, per-variable counts and the summary, not each difference\n"
         "  exit status: 0 within tolerance, 1 differences, 2 usage or I/O error\n";
}

}  // namespace

int main(int argc, char** argv) {
  bool quiet = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-q") {
      quiet = true;
    } else if (arg == "-h" || arg == "--help") {
      usage(std::cout);
      return 0;
    } else if (arg.size() > 1 && arg[0] == '-') {
      std::cerr << "peridot-diff: unknown option " << arg << "\n";
      usage(std::cerr);
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.size() != 3) {
    usage(std::cerr);
    return 2;
  }
  try {
    const peridot::CompSpec spec = peridot::parseCompFile(files[0]);
    const peridot::ExodusResults result = peridot::readExodusResults(files[1]);
    const peridot::ExodusResults gold = peridot::readExodusResults(files[2]);
    const peridot::CompareReport report = peridot::compareExodusResults(result, gold, spec);
    std::cout << "peridot-diff: " << files[1] << " vs gold " << files[2] << " (" << files[0]
              << ")\n";
    peridot::printCompareReport(std::cout, report, quiet);
    return report.passed() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "peridot-diff: " << e.what() << "\n";
    return 2;
  }
}
