#pragma once
// Checks of a deck's raw text made before the Teuchos readers see it. The readers recurse once
// per nesting level (a deck nested 10,000 lists deep overflows the stack) and the YAML reader
// slows quadratically with the length of a line, so the limits are enforced here, on the bytes,
// where they cost one linear pass. The YAML checks also put the common syntax mistakes (an
// unclosed bracket or quote, a misaligned key) in words with their line, which the YAML
// reader reports only as a parser state number.
#include <string>

namespace peridot {

struct DeckLimits {
  static constexpr std::size_t kMaxBytes = 64u << 20;     // a deck is text, not data
  static constexpr int kMaxDepth = 64;                    // real decks nest about 5 deep
  static constexpr std::size_t kMaxYamlLine = 64u << 10;  // 64 KiB: about 1 s in the reader
  static constexpr std::size_t kMaxMessageWord = 120;     // longest unbroken text in a message
};

// Throws InputError naming `fileName` and the line if `text` breaks a limit or (YAML) has an
// unclosed bracket or quote or a misaligned key.
void screenDeckText(const std::string& text, bool yaml, const std::string& fileName);

// Explains a Teuchos YAML parser failure ("Parser failure at line L column C ...; Parser was in
// state N") in words, quoting the line; returns "" if `what` is not such a message.
std::string explainYamlFailure(const std::string& what, const std::string& text);

// A message with every unbroken run of more than kMaxMessageWord characters cut to its start
// and its length, so an error about a 10 MB name stays one readable line.
std::string shortenForMessage(const std::string& message);

}  // namespace peridot
