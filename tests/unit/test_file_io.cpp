// The one writer of output files and the bounded reader (core/file_io.h), and
// the quoting of outside text in messages (core/message.h).
#include "core/error.h"
#include "core/file_io.h"
#include "core/message.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <csignal>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rl;

namespace {

fs::path freshDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("raylab_file_io_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string errorOf(const fs::path& path, const std::string& content, const char* what = "PNG") {
    try {
        writeFileAtomic(path, content, WriteOptions{what});
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string contentOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

int entries(const fs::path& dir) { return int(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }

}  // namespace

TEST(FileIo, WritesReplacesAndKeepsTheMode) {
    fs::path dir = freshDir("write");
    writeFileAtomic(dir / "a.txt", "first");
    EXPECT_EQ(contentOf(dir / "a.txt"), "first");
    chmod((dir / "a.txt").c_str(), 0640);
    writeFileAtomic(dir / "a.txt", "second");
    EXPECT_EQ(contentOf(dir / "a.txt"), "second");
    struct stat st {};
    stat((dir / "a.txt").c_str(), &st);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    EXPECT_EQ(entries(dir), 1);  // no temporary file left beside it
    fs::remove_all(dir);
}

TEST(FileIo, ALinkKeepsPointingAtTheReplacedFile) {
    fs::path dir = freshDir("link");
    writeFileAtomic(dir / "real.txt", "old");
    fs::create_symlink("real.txt", dir / "link.txt");
    writeFileAtomic(dir / "link.txt", "new");
    EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
    EXPECT_EQ(contentOf(dir / "real.txt"), "new");
    fs::remove_all(dir);
}

TEST(FileIo, DeviceFifoAndFolderAreRefusedAndKept) {
    fs::path dir = freshDir("special");
    // A scratch copy of /dev/full (character device 1:7), never the real one.
    fs::path full = dir / "full";
    bool haveDevice = mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0;
    if (haveDevice) {
        EXPECT_EQ(errorOf(full, "x"),
                  full.string() + ": cannot write PNG (a character device, not a regular file; name a file to write)");
        struct stat st {};
        ASSERT_EQ(stat(full.c_str(), &st), 0) << "the device node was deleted";
        EXPECT_TRUE(S_ISCHR(st.st_mode));
    }
    fs::path fifo = dir / "fifo";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(errorOf(fifo, "x"), fifo.string() + ": cannot write PNG (a FIFO, not a regular file; name a file to write)");
    EXPECT_TRUE(fs::is_fifo(fifo));
    fs::create_directory(dir / "folder");
    EXPECT_EQ(errorOf(dir / "folder", "x"),
              (dir / "folder").string() + ": cannot write PNG (a directory, not a regular file; name a file to write)");
    EXPECT_TRUE(fs::is_directory(dir / "folder"));
    EXPECT_EQ(entries(dir), haveDevice ? 3 : 2);
    fs::remove_all(dir);
}

TEST(FileIo, AFailedWriteKeepsTheOldContent) {
    fs::path dir = freshDir("fail");
    writeFileAtomic(dir / "a.png", "old picture");
    // A folder we may not write: the temporary file cannot be made, the old file stays.
    fs::create_directory(dir / "ro");
    writeFileAtomic(dir / "ro" / "b.png", "old");
    chmod((dir / "ro").c_str(), 0555);
    if (geteuid() != 0) {  // root writes anywhere
        EXPECT_EQ(errorOf(dir / "ro" / "b.png", "new").rfind((dir / "ro" / "b.png").string() + ": cannot write PNG (", 0),
                  0u);
        EXPECT_EQ(contentOf(dir / "ro" / "b.png"), "old");
    }
    chmod((dir / "ro").c_str(), 0755);
    EXPECT_EQ(errorOf(dir / "missing" / "a.png", "x"),
              (dir / "missing" / "a.png").string() + ": cannot write PNG (No such file or directory)");
    EXPECT_EQ(contentOf(dir / "a.png"), "old picture");
    fs::remove_all(dir);
}

TEST(FileIo, AFullDiskKeepsTheOldContentAndLeavesNoTemporaryFile) {
    // RLIMIT_FSIZE makes write() fail with EFBIG like a full disk would with ENOSPC.
    fs::path dir = freshDir("full");
    writeFileAtomic(dir / "a.png", "old picture");
    pid_t child = fork();
    if (child == 0) {
        signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            writeFileAtomic(dir / "a.png", std::string(100000, 'x'), WriteOptions{"PNG"});
        } catch (const Error& e) {
            _exit(std::string(e.what()) == (dir / "a.png").string() + ": cannot write PNG (File too large)" ? 0 : 2);
        }
        _exit(1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    EXPECT_EQ(contentOf(dir / "a.png"), "old picture");
    EXPECT_EQ(entries(dir), 1);
    fs::remove_all(dir);
}

TEST(FileIo, ReadsOnlyBoundedRegularFiles) {
    fs::path dir = freshDir("read");
    auto errorReading = [](const fs::path& p, std::uintmax_t limit) {
        try {
            readRegularFile(p, limit, "the scene");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    writeFileAtomic(dir / "a.json", "12345");
    EXPECT_EQ(readRegularFile(dir / "a.json", 5), "12345");
    EXPECT_EQ(errorReading(dir / "a.json", 4), (dir / "a.json").string() + ": cannot read the scene (larger than 4 bytes)");
    EXPECT_EQ(errorReading(dir / "none", 4), (dir / "none").string() + ": cannot read the scene (not found)");
    EXPECT_EQ(errorReading(dir, 4), dir.string() + ": cannot read the scene (is a directory)");
    ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
    EXPECT_EQ(errorReading(dir / "fifo", 4), (dir / "fifo").string() + ": cannot read the scene (not a regular file: a FIFO)");
    fs::remove_all(dir);
}

TEST(Message, QuotedValuesAreShortAndPrintable) {
    EXPECT_EQ(quotedValue("aces"), "'aces'");
    EXPECT_EQ(quotedValue(std::string(100, 'x'), 4), "'xxxx...' (100 bytes)");
    EXPECT_EQ(quotedValue("\x1b[2J\n\t\r\x7f"), "'\\x1b[2J\\n\\t\\r\\x7f'");
    EXPECT_EQ(quotedValue("caf\xc3\xa9 \xff"), "'caf\xc3\xa9 \\xff'");  // UTF-8 kept, a stray byte escaped
    EXPECT_EQ(quotedValue("\xc2\x9b" "31m"), "'\\u009b31m'");            // C1 CSI: some terminals obey it
    EXPECT_EQ(oneLine("a\nb", 10), "a\\nb");
    EXPECT_EQ(printableLines("a\nb\x1b", 10), "a\nb\\x1b");
}
