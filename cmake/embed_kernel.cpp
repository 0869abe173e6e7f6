// Build-time tool: inlines cl/kernel.cl and every header it includes with #include "..."
// (each once, relative to the including file) into one C++ string literal, so the
// executable carries its kernel and runs from any directory.
// Usage: embed_kernel INPUT.cl OUTPUT.cpp
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

static bool inline_file(const fs::path& path, std::set<fs::path>& seen, std::string& out) {
  fs::path abs = fs::weakly_canonical(path);
  if (!seen.insert(abs).second) return true;
  std::ifstream in(abs);
  if (!in) {
    std::cerr << "embed_kernel: cannot read " << abs << "\n";
    return false;
  }
  std::string line;
  const std::string directive = "#include \"";
  while (std::getline(in, line)) {
    if (line.compare(0, directive.size(), directive) == 0) {
      size_t end = line.find('"', directive.size());
      fs::path inc = abs.parent_path() / line.substr(directive.size(), end - directive.size());
      if (!inline_file(inc, seen, out)) return false;
    } else {
      out += line;
      out += '\n';
    }
  }
  return true;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: embed_kernel INPUT.cl OUTPUT.cpp\n";
    return 2;
  }
  std::set<fs::path> seen;
  std::string source;
  if (!inline_file(argv[1], seen, source)) return 1;
  std::ofstream out(argv[2]);
  out << "// Generated from " << fs::path(argv[1]).filename().string()
      << " by cmake/embed_kernel.cpp.\n#include \"device/cl/cl_program.h\"\nnamespace rt {\n"
      << "const char* const kKernelSource = R\"RTCL(" << source << ")RTCL\";\n}\n";
  return out ? 0 : 1;
}
