// The subcommands of `compare`. Each takes the full argv (argv[1] is its name) and returns
// the exit status: 0 pass, 1 fail, 2 bad usage or unreadable input.
#pragma once

namespace cmp {

int run_welch(int argc, char** argv);
int run_paired(int argc, char** argv);
int run_exact(int argc, char** argv);
int run_diff(int argc, char** argv);
int run_report(int argc, char** argv);     // Exit 0 once the page is written.
int run_reference(int argc, char** argv);  // 0 pass, 1 fail.
int run_summary(int argc, char** argv);    // 0.

}  // namespace cmp
