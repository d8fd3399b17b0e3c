// Every C++ snippet of the README is part of a program under examples/ (which ctest builds
// and runs), so the README cannot teach code that does not compile or work.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string readFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The lines of `text` without their indentation and trailing spaces.
std::vector<std::string> trimmedLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find_first_not_of(' ');
    const std::size_t last = line.find_last_not_of(' ');
    lines.push_back(first == std::string::npos ? "" : line.substr(first, last - first + 1));
  }
  return lines;
}

std::vector<std::string> cppSnippets(const std::string& markdown) {
  std::vector<std::string> snippets;
  const std::string open = "```cpp\n";
  for (std::size_t at = markdown.find(open); at != std::string::npos;
       at = markdown.find(open, at)) {
    const std::size_t start = at + open.size();
    const std::size_t end = markdown.find("```", start);
    snippets.push_back(markdown.substr(start, end - start));
    at = end;
  }
  return snippets;
}

bool containsLines(const std::vector<std::string>& program, const std::vector<std::string>& lines) {
  return std::search(program.begin(), program.end(), lines.begin(), lines.end()) != program.end();
}

TEST(ReadmeSnippets, EachIsPartOfAnExampleProgram) {
  const std::filesystem::path root = LCMTF_SOURCE_DIR;
  std::vector<std::pair<std::string, std::vector<std::string>>> programs;
  for (const auto& entry : std::filesystem::directory_iterator(root / "examples")) {
    if (entry.path().extension() == ".cpp") {
      programs.emplace_back(entry.path().filename(), trimmedLines(readFile(entry.path())));
    }
  }
  const std::vector<std::string> snippets = cppSnippets(readFile(root / "README.md"));
  ASSERT_GE(snippets.size(), 2u);
  for (const std::string& snippet : snippets) {
    const std::vector<std::string> lines = trimmedLines(snippet);
    bool found = false;
    for (const auto& [name, program] : programs) found = found || containsLines(program, lines);
    EXPECT_TRUE(found) << "README snippet found in no program under examples/:\n" << snippet;
  }
}

}  // namespace
