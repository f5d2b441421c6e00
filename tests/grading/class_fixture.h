// A class of submissions built at test time from solutions/, the stubs in
// exercises/ and tests/mutants/: one student per case the grader must
// survive, each with the marks and reason a test expects.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rl::test {

struct ZipEntry {
    std::string name;
    std::string content;   // for a symlink: its target
    bool symlink = false;
};

// Writes a zip with libzip (symlink entries carry Unix S_IFLNK attributes).
void writeZip(const std::filesystem::path& path, const std::vector<ZipEntry>& entries);

// solutions/*.glsl as a map file name -> text; `replace` swaps some files.
std::map<std::string, std::string> solutionFiles(const std::map<std::string, std::string>& replace = {});
std::map<std::string, std::string> stubFiles();
void writeFolder(const std::filesystem::path& dir, const std::map<std::string, std::string>& files);

// tests/mutants/<name>.glsl, and the phrase its header says the check reports
// (`// caught by: the check's message or hint contains "..."`).
std::string mutantText(const std::string& name);
std::string mutantCaughtBy(const std::string& name);

// 10-display.glsl whose toneMap never ends. llvmpipe stops any shader's loops
// after 65535 iterations in all (LP_MAX_TGSI_LOOP_ITERATIONS), so an empty
// `while (true) {}` ends at once with a wrong result; this loop does 256
// sin() per iteration, which keeps llvmpipe busy for hours, as an endless
// loop would keep a GPU driver without that cap.
std::string endlessDisplay();
// 03-lambert.glsl whose Fd_Lambert is 0/0 at run time: NaN everywhere it lights.
std::string nanLambert();
// 05-ggx.glsl with a syntax error on line 3.
std::string compileErrorGgx();

// 08-cook-torrance.glsl as a student wrote it: the solution's specular lobe
// rewritten with three helper functions of their own (correct: PASS).
// `author` 0..N gives a differently written file each (other helpers, other
// statements), as independent students would.
std::string ownCookTorrance(int author = 0);
// The same file with every identifier of the student's own renamed
// (`prefix` + a number), and with its functions in reverse order.
std::string renamedCopy(const std::string& text, const std::string& prefix);
std::string reorderedCopy(const std::string& text);

}  // namespace rl::test
