#include "grading/safe_unzip.h"

#include "core/error.h"
#include "core/file_handle.h"

#include <zip.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

namespace fs = std::filesystem;

namespace rl {

namespace {

// The file type bits of a Unix st_mode, as Info-ZIP stores them in the top
// half of an entry's external attributes (the same values on every system).
constexpr std::uint32_t kModeTypeMask = 0170000, kModeLink = 0120000, kModeRegular = 0100000,
                        kModeDirectory = 0040000;

struct ZipCloser {
    void operator()(zip_t* z) const { zip_discard(z); }  // read-only: never write the archive back
};
struct ZipFileCloser {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

// The entry's path split into components, or an empty vector plus the reason
// when the name could leave the destination.
std::vector<std::string> safeComponents(const std::string& name, std::string& why) {
    std::vector<std::string> parts;
    if (name.empty()) {
        why = "an entry has an empty name";
        return {};
    }
    if (name[0] == '/') {
        why = "entry \"" + name + "\" has an absolute path";
        return {};
    }
    if (name.size() >= 2 && name[1] == ':') {
        why = "entry \"" + name + "\" names a drive";
        return {};
    }
    for (unsigned char c : name)
        if (c < 0x20 || c == 0x7f || c == '\\') {
            why = "entry \"" + name + "\" has a backslash or control character in its name";
            return {};
        }
    std::size_t start = 0;
    while (start <= name.size()) {
        std::size_t slash = name.find('/', start);
        std::string part = name.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
        if (part == "..") {
            why = "entry \"" + name + "\" climbs out of the archive with \"..\"";
            return {};
        }
        if (!part.empty() && part != ".") parts.push_back(part);
        if (slash == std::string::npos) break;
        start = slash + 1;
    }
    if (parts.size() > 16) {
        why = "entry \"" + name + "\" is nested too deeply";
        return {};
    }
    return parts;
}


struct Entry {
    zip_uint64_t index;
    std::vector<std::string> parts;
    bool directory;
};

template <class Fail>
void extractEntries(zip_t* archive, const std::vector<Entry>& entries, const fs::path& dest,
                    const UnzipLimits& limits, UnzipResult& result, const Fail& fail) {
    std::error_code ec;
    std::uint64_t total = 0;
    std::vector<char> buffer(1 << 16);
    for (const Entry& e : entries) {
        fs::path target = dest;
        for (const std::string& part : e.parts) target /= part;
        if (e.directory) {
            fs::create_directories(target, ec);
            if (ec) throw fail("entry \"" + target.lexically_relative(dest).string() + "\" cannot be created");
            continue;
        }
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw fail("entry \"" + target.lexically_relative(dest).string() + "\" cannot be created");
        std::unique_ptr<zip_file_t, ZipFileCloser> in(zip_fopen_index(archive, e.index, 0));
        if (!in) throw fail("entry \"" + target.lexically_relative(dest).string() + "\" cannot be read (" +
                            zip_strerror(archive) + ")");
        // Created new: a duplicate entry never overwrites, and never through a link.
        NewFile out(target);
        if (!out.ok()) {
            if (out.exists()) {
                result.refused[target.lexically_relative(dest).generic_string()] = "a duplicate entry in the zip";
                continue;
            }
            throw fail("entry \"" + target.lexically_relative(dest).string() + "\" cannot be written (" +
                       out.error().message() + ")");
        }
        std::uint64_t entryBytes = 0;
        for (;;) {
            zip_int64_t n = zip_fread(in.get(), buffer.data(), buffer.size());
            if (n < 0)
                throw fail("entry \"" + target.lexically_relative(dest).string() + "\" is corrupt (" +
                           zip_file_strerror(in.get()) + ")");
            if (n == 0) break;
            entryBytes += zip_uint64_t(n);
            total += zip_uint64_t(n);
            if (entryBytes > limits.maxEntryBytes || total > limits.maxTotalBytes)
                throw fail("inflates past the size limit (" + std::to_string(limits.maxTotalBytes >> 20) +
                           " MiB in all, " + std::to_string(limits.maxEntryBytes >> 20) + " MiB per entry)");
            if (!out.write(buffer.data(), std::size_t(n)))
                throw fail("entry \"" + target.lexically_relative(dest).string() + "\" cannot be written (" +
                           out.error().message() + ")");
        }
        ++result.files;
    }
}

}  // namespace

UnzipResult extractZipSafely(const fs::path& zipPath, const fs::path& dest, const UnzipLimits& limits,
                             const UnzipFilter& wanted) {
    const std::string shown = zipPath.filename().string();
    auto fail = [&](const std::string& why) { return Error(shown + ": " + why); };
    int code = 0;
    std::unique_ptr<zip_t, ZipCloser> archive(zip_open(zipPath.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &code));
    if (!archive) {
        zip_error_t error;
        zip_error_init_with_code(&error, code);
        std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw fail("not a valid zip archive (" + why + ")");
    }
    zip_int64_t count = zip_get_num_entries(archive.get(), 0);
    if (count < 0) throw fail("not a valid zip archive");
    const std::size_t listedLimit = wanted ? limits.maxListedEntries : limits.maxEntries;
    if (std::size_t(count) > listedLimit)
        throw fail("holds " + std::to_string(count) + " entries, over the limit of " + std::to_string(listedLimit));

    // First pass: names, types and declared sizes, so that a bad archive is
    // refused before anything is written.
    std::vector<Entry> entries;
    UnzipResult result;
    std::uint64_t declaredTotal = 0;
    for (zip_int64_t i = 0; i < count; ++i) {
        zip_stat_t st;
        zip_stat_init(&st);
        if (zip_stat_index(archive.get(), zip_uint64_t(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
            throw fail("entry " + std::to_string(i) + " cannot be read (" + zip_strerror(archive.get()) + ")");
        std::string name = st.name;
        std::string why;
        std::vector<std::string> parts = safeComponents(name, why);
        if (!why.empty()) throw fail("refused: " + why);
        if (parts.empty()) continue;  // "./" and the like
        std::string key = parts[0];
        for (std::size_t k = 1; k < parts.size(); ++k) key += "/" + parts[k];
        bool directory = name.back() == '/';
        if (wanted && (directory || !wanted(key))) {
            if (!directory) result.skipped.push_back(key);
            continue;  // never written: no limit applies, the name was checked above
        }
        zip_uint8_t opsys = 0;
        zip_uint32_t attributes = 0;
        if (zip_file_get_external_attributes(archive.get(), zip_uint64_t(i), 0, &opsys, &attributes) == 0 &&
            opsys == ZIP_OPSYS_UNIX) {
            const std::uint32_t type = (attributes >> 16) & kModeTypeMask;
            if (type == kModeLink) {
                result.refused[key] = "a symbolic link in the zip (links are not followed)";
                continue;
            }
            if (type != 0 && type != kModeRegular && type != kModeDirectory) {
                result.refused[key] = "not a regular file";
                continue;
            }
            directory = directory || type == kModeDirectory;
        }
        if (!directory) {
            if ((st.valid & ZIP_STAT_ENCRYPTION_METHOD) && st.encryption_method != ZIP_EM_NONE)
                throw fail("entry \"" + name + "\" is encrypted");
            if ((st.valid & ZIP_STAT_SIZE) && st.size > limits.maxEntryBytes)
                throw fail("entry \"" + name + "\" inflates to " + std::to_string(st.size >> 20) +
                           " MiB, over the limit of " + std::to_string(limits.maxEntryBytes >> 20) + " MiB");
            if ((st.valid & ZIP_STAT_SIZE) && (st.valid & ZIP_STAT_COMP_SIZE) && st.size > limits.ratioCheckAbove &&
                double(st.size) > limits.maxRatio * double(std::max<zip_uint64_t>(st.comp_size, 1)))
                throw fail("entry \"" + name + "\" has a compression ratio over " +
                           std::to_string(int(limits.maxRatio)) + ":1 (a zip bomb?)");
            if (st.valid & ZIP_STAT_SIZE) declaredTotal += st.size;
        }
        entries.push_back({zip_uint64_t(i), parts, directory});
    }
    if (entries.size() > limits.maxEntries)
        throw fail("holds " + std::to_string(entries.size()) + " entries to extract, over the limit of " +
                   std::to_string(limits.maxEntries));
    if (declaredTotal > limits.maxTotalBytes)
        throw fail("inflates to " + std::to_string(declaredTotal >> 20) + " MiB, over the limit of " +
                   std::to_string(limits.maxTotalBytes >> 20) + " MiB");

    // Second pass: extract, counting the bytes actually inflated. A failure
    // removes what was extracted, so a refused archive leaves nothing behind.
    std::error_code ec;
    fs::create_directories(dest, ec);
    if (ec) throw Error(dest.string() + ": cannot create (" + ec.message() + ")");
    try {
        extractEntries(archive.get(), entries, dest, limits, result, fail);
    } catch (...) {
        fs::remove_all(dest, ec);
        throw;
    }
    return result;
}

}  // namespace rl
