#include "base/nearest_word.hpp"

#include <algorithm>
#include <vector>

namespace l2 {
namespace {

// Edits from a to b: insertions, deletions, substitutions and swaps of neighbours (optimal string
// alignment distance).
std::size_t edits(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::optional<std::string_view> nearest_word(std::string_view word,
                                             std::initializer_list<std::string_view> choices) {
  // A key of any length is never compared against a whole file's worth of text: bounded work.
  if (word.size() > 64) return std::nullopt;
  const std::size_t most = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string_view> best;
  std::size_t best_edits = most + 1;
  for (const std::string_view c : choices) {
    if (c.size() > 64) continue;
    const std::size_t e = edits(word, c);
    if (e < best_edits) {
      best = c;
      best_edits = e;
    }
  }
  return best;
}

std::string word_list(std::initializer_list<std::string_view> choices) {
  std::string out;
  for (const std::string_view c : choices) {
    if (!out.empty()) out += ", ";
    out += c;
  }
  return out;
}

}  // namespace l2
