#pragma once

#include <string>
#include <vector>

namespace lcmtf::nodes {

/// Text in aligned columns under a header line; columns marked numeric are right-aligned.
class TextTable {
 public:
  TextTable(std::vector<std::string> headers, std::vector<bool> numeric);
  /// A row with one cell per column (missing cells are empty).
  void addRow(std::vector<std::string> cells);
  /// Every line starts with `indent`; trailing spaces are trimmed.
  std::string render(const std::string& indent = "  ") const;

 private:
  std::vector<std::string> headers_;
  std::vector<bool> numeric_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace lcmtf::nodes
