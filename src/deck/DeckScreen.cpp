#include "deck/DeckScreen.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/Error.hpp"

namespace peridot {

namespace {

std::string lineText(const std::string& text, std::size_t line) {
  std::size_t start = 0;
  for (std::size_t l = 1; l < line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || start > text.size()) return "";
  std::size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  std::string s = text.substr(start, std::min<std::size_t>(end - start, 200));
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
  const std::size_t b = s.find_first_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b);
}

struct Opening {
  char bracket;
  std::size_t line, column;
};

// One lenient pass over YAML text: nesting depth (indentation levels plus open flow brackets),
// and the first unclosed or mismatched bracket or quote. It follows only what Peridigm decks use
// (block maps, flow maps and lists, quoted and plain scalars, comments); the YAML reader stays the
// judge of validity.
struct YamlScan {
  int maxDepth = 0;
  std::size_t deepLine = 0;
  std::string bracketProblem;  // an unclosed or mismatched bracket or quote, in words
};

YamlScan scanYaml(const std::string& text) {
  YamlScan scan;
  std::vector<int> indents;  // block levels open at this point
  std::vector<Opening> flow;
  char quote = 0;  // open quote spanning lines
  std::size_t quoteLine = 0, quoteColumn = 0;
  int blockScalarIndent = -1;  // inside a `|` or `>` scalar: lines deeper than this are text
  std::size_t line = 0, pos = 0;
  while (pos <= text.size() && scan.bracketProblem.empty()) {
    ++line;
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string s = text.substr(pos, end - pos);
    pos = end + 1;
    const std::size_t first = s.find_first_not_of(" \r");
    const bool blank = first == std::string::npos || s[first] == '#';
    const int indent = first == std::string::npos ? 0 : static_cast<int>(first);
    if (blockScalarIndent >= 0) {
      if (blank || indent > blockScalarIndent) continue;
      blockScalarIndent = -1;
    }
    if (blank && quote == 0) continue;
    if (flow.empty() && quote == 0) {
      if (s.compare(first, 3, "---") == 0 || s.compare(first, 3, "...") == 0) continue;
      while (!indents.empty() && indents.back() > indent) indents.pop_back();
      if (indents.empty() || indents.back() < indent) {
        // A line deeper than the last level opens a level if the line before ended a key.
        indents.push_back(indent);
      }
      const int depth = static_cast<int>(indents.size());
      if (depth > scan.maxDepth) {
        scan.maxDepth = depth;
        scan.deepLine = line;
      }
    }
    // Walk the characters for brackets and quotes.
    char prev = ' ';  // last non-blank character outside quotes on this line
    for (std::size_t c = quote ? 0 : first; c < s.size(); ++c) {
      const char ch = s[c];
      if (quote) {
        if (quote == '"' && ch == '\\') {
          ++c;
          continue;
        }
        if (ch == quote) {
          if (quote == '\'' && c + 1 < s.size() && s[c + 1] == '\'') {
            ++c;
            continue;
          }
          quote = 0;
          prev = 'q';
        }
        continue;
      }
      if (ch == ' ' || ch == '\r' || ch == '\t') continue;
      if (ch == '#' && (c == 0 || s[c - 1] == ' ')) break;
      const bool valueStart =
          prev == ' ' || prev == ':' || prev == '-' || prev == '[' || prev == '{' || prev == ',';
      const bool inFlow = !flow.empty();
      if ((ch == '"' || ch == '\'') && valueStart) {
        quote = ch;
        quoteLine = line;
        quoteColumn = c + 1;
        continue;
      }
      if ((ch == '[' || ch == '{') && (inFlow || valueStart)) {
        flow.push_back({ch, line, c + 1});
        const int depth = static_cast<int>(indents.size() + flow.size());
        if (depth > scan.maxDepth) {
          scan.maxDepth = depth;
          scan.deepLine = line;
        }
      } else if ((ch == ']' || ch == '}') && inFlow) {
        const char want = flow.back().bracket == '[' ? ']' : '}';
        if (ch != want) {
          scan.bracketProblem = "the '" + std::string(1, ch) + "' at line " + std::to_string(line) +
                                " column " + std::to_string(c + 1) + " does not close the '" +
                                std::string(1, flow.back().bracket) + "' opened at line " +
                                std::to_string(flow.back().line) + " column " +
                                std::to_string(flow.back().column) + " (expected '" +
                                std::string(1, want) + "')";
          break;
        }
        flow.pop_back();
      } else if ((ch == '|' || ch == '>') && prev == ':' && flow.empty()) {
        blockScalarIndent = indent;
      }
      prev = ch;
    }
  }
  if (scan.bracketProblem.empty() && quote != 0) {
    scan.bracketProblem = std::string("the ") + (quote == '"' ? "double" : "single") +
                          " quote opened at line " + std::to_string(quoteLine) + " column " +
                          std::to_string(quoteColumn) + " is never closed";
  } else if (scan.bracketProblem.empty() && !flow.empty()) {
    scan.bracketProblem = "the '" + std::string(1, flow.back().bracket) + "' opened at line " +
                          std::to_string(flow.back().line) + " column " +
                          std::to_string(flow.back().column) + " is never closed (expected '" +
                          (flow.back().bracket == '[' ? "]" : "}") + "')";
  }
  return scan;
}

// Element depth of XML text; comments, declarations and CDATA do not nest.
void screenXmlDepth(const std::string& text, const std::string& fileName) {
  int depth = 0;
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') ++line;
    if (ch != '<' || i + 1 >= text.size()) continue;
    const char next = text[i + 1];
    if (next == '!' || next == '?') {
      const char* close = text.compare(i, 4, "<!--") == 0 ? "-->" : ">";
      const std::size_t e = text.find(close, i + 1);
      if (e == std::string::npos) return;  // the XML reader reports it
      line += static_cast<std::size_t>(std::count(text.begin() + i, text.begin() + e, '\n'));
      i = e;
      continue;
    }
    if (next == '/') {
      --depth;
      continue;
    }
    const std::size_t e = text.find('>', i + 1);
    if (e == std::string::npos) return;
    if (text[e - 1] == '/') continue;  // <Parameter .../>
    if (++depth > DeckLimits::kMaxDepth) {
      throw InputError("deck file \"" + fileName + "\" nests lists more than " +
                       std::to_string(DeckLimits::kMaxDepth) + " deep (at line " +
                       std::to_string(line) + "); Peridigm decks nest about 5 deep");
    }
  }
}

}  // namespace

void screenDeckText(const std::string& text, bool yaml, const std::string& fileName) {
  const std::string deck = "deck file \"" + fileName + "\"";
  if (text.size() > DeckLimits::kMaxBytes) {
    throw InputError(deck + " is " + std::to_string(text.size()) +
                     " bytes long; decks are limited to " +
                     std::to_string(DeckLimits::kMaxBytes >> 20) +
                     " MiB (put long node set lists in node set files)");
  }
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + nul, '\n');
    throw InputError(deck + " holds a NUL byte at line " + std::to_string(line) +
                     " (a binary file, or a damaged deck?)");
  }
  if (!yaml) {
    screenXmlDepth(text, fileName);
    return;
  }
  std::size_t line = 1, start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end - start > DeckLimits::kMaxYamlLine) {
      throw InputError(deck + ": line " + std::to_string(line) + " is " +
                       std::to_string(end - start) +
                       " characters long; YAML decks are limited to " +
                       std::to_string(DeckLimits::kMaxYamlLine) +
                       " characters a line (the YAML reader slows down with the square of a "
                       "line's length; put long node set lists in node set files)");
    }
    start = end + 1;
    ++line;
  }
  const YamlScan scan = scanYaml(text);
  if (scan.maxDepth > DeckLimits::kMaxDepth) {
    throw InputError(deck + " nests lists more than " + std::to_string(DeckLimits::kMaxDepth) +
                     " deep (at line " + std::to_string(scan.deepLine) +
                     "); Peridigm decks nest about 5 deep");
  }
  if (!scan.bracketProblem.empty()) {
    throw InputError("cannot parse deck file \"" + fileName + "\" as YAML: " + scan.bracketProblem);
  }
}

std::string explainYamlFailure(const std::string& what, const std::string& text) {
  const std::size_t at = what.find("at line ");
  if (at == std::string::npos || what.find("Parser was in state") == std::string::npos) return "";
  const std::size_t line = std::strtoul(what.c_str() + at + 8, nullptr, 10);
  const std::size_t col = what.find("column ", at);
  const std::size_t column =
      col == std::string::npos ? 0 : std::strtoul(what.c_str() + col + 7, nullptr, 10);
  std::string out = "the YAML syntax breaks at line " + std::to_string(line);
  if (column > 0) out += " column " + std::to_string(column);
  const std::string here = lineText(text, line);
  if (!here.empty()) out += " (\"" + here + "\")";
  if (here.find(": ") != std::string::npos &&
      here.find(": ", here.find(": ") + 2) != std::string::npos &&
      here.find_first_of("\"'{[") == std::string::npos) {
    out += ": a value may not hold \": \" unless it is quoted";
  } else {
    out +=
        ": expected \"key: value\" or \"key:\" indented like the keys around it (spaces only; "
        "nested keys deeper than their parent, siblings at the same column)";
  }
  return out;
}

std::string shortenForMessage(const std::string& message) {
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    std::size_t j = i;
    while (j < message.size() && message[j] != ' ' && message[j] != '\n') ++j;
    const std::size_t n = j - i;
    if (n > DeckLimits::kMaxMessageWord) {
      // Punctuation that ends the run (the ": " after a key) stays after the marker.
      std::size_t keep = n;
      while (keep > 0 && (message[i + keep - 1] == ':' || message[i + keep - 1] == ',' ||
                          message[i + keep - 1] == ';'))
        --keep;
      out.append(message, i, 60);
      out += "...[" + std::to_string(keep) + " characters]";
      out.append(message, i + keep, n - keep);
    } else {
      out.append(message, i, n);
    }
    if (j < message.size()) out += message[j] == '\n' ? ' ' : message[j];
    i = j + 1;
  }
  return out;
}

}  // namespace peridot
