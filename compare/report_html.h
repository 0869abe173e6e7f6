// The page `compare report` writes: one self-contained HTML file (every image a PNG in a
// data: URI) that opens from disk in any browser. A small script at its end counts the
// images the browser decoded into #load-check, which tests/compare/report_browser.sh reads.
#pragma once

#include <string>

#include "inputs.h"
#include "report_model.h"

namespace cmp {

// The page for `analysis` of B against A.
std::string report_html(const Side& a, const Side& b, const Analysis& analysis,
                        const ReportOptions& o);

// Where the page goes: `out` itself, or out/report.html when `out` is a directory (an
// existing one, or a name ending in '/', which is created).
std::string report_path(const std::string& out);

// Writes `html` to `path` atomically. Throws std::runtime_error naming the file.
void write_report(const std::string& path, const std::string& html);

}  // namespace cmp
