#pragma once
// "did you mean" for names typed in a deck: the known name that differs only in case, blanks,
// '_' or '-', or by at most two edits (a third of the name's length at most).
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace peridot {

inline std::string foldName(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '_' && c != '-')
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

inline std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// " (did you mean "Elastic"?)" or "".
inline std::string didYouMean(const std::string& name, const std::vector<std::string>& known) {
  if (name.size() > 200) return "";  // a long value is no typo of a model name
  const std::string f = foldName(name);
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(1, std::min<std::size_t>(2, f.size() / 3)) + 1;
  for (const auto& k : known) {
    const std::string g = foldName(k);
    const std::size_t d = g == f ? 0 : editDistance(f, g);
    if (d < bestDistance) {
      bestDistance = d;
      best = k;
    }
  }
  return best.empty() ? "" : " (did you mean \"" + best + "\"?)";
}

}  // namespace peridot
