// Reading the student documents as a student does: the code blocks of a
// Markdown file (fenced or indented), the commands in them and in inline code
// spans, and the checker output the documents show.
#pragma once

#include <string>
#include <vector>

namespace rl::walkthrough {

struct CodeBlock {
    int line = 0;                    // 1-based line of the block's first line in the document
    std::vector<std::string> lines;  // common indentation removed, no trailing blank lines
};

// Fenced (``` or ~~~) and indented (4 spaces, after a blank line) code blocks.
std::vector<CodeBlock> codeBlocks(const std::string& markdown);

struct DocCommand {
    int line = 0;
    std::string text;  // as written, e.g. "./raylab check --exercise 1"
};

// Every command a student would type: the lines of code blocks that start
// with "./raylab ", "scripts/" or "cmake ", and inline code spans that start
// with "./raylab ". In document order, each distinct command once.
std::vector<DocCommand> commands(const std::string& markdown);

// Checker output shown in a document: code blocks whose first line is a
// verdict line ("07-fresnel        FAIL          ...") or a hint line.
std::vector<CodeBlock> checkerOutputs(const std::string& markdown);

// The value of option `name` ("-o") in a command, or "" when absent.
std::string optionValue(const std::string& command, const std::string& name);

// True when every line of `shown` (a block of checker output in a document)
// appears in `output`, in order. White space runs count as one space, "(12 s)"
// matches any duration, a line "..." stands for any lines, and a line ending
// in "..." matches any line that starts with what precedes it.
bool showsOutput(const std::vector<std::string>& shown, const std::string& output);

}  // namespace rl::walkthrough
