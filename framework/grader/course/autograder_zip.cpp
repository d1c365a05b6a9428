// Gradescope's zip, written with libzip (not part of a grading-only build: RAYLAB_GRADING_ONLY).
#include "grader/course/autograder.h"

#include <zip.h>

#include <random>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

struct ZipArchive {
    zip_t* archive = nullptr;
    ~ZipArchive() {
        if (archive) zip_discard(archive);
    }
};

[[noreturn]] void zipFailure(zip_t* archive, const std::string& what) {
    throw std::runtime_error(what + ": " + zip_strerror(archive));
}

} // namespace

void writeZip(const fs::path& zip, const std::vector<ZipEntry>& entries) {
    std::random_device random;
    const fs::path temporary = zip.string() + ".tmp-" + std::to_string(random());
    int code = 0;
    ZipArchive archive;
    archive.archive = zip_open(temporary.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
    if (!archive.archive) {
        zip_error_t error;
        zip_error_init_with_code(&error, code);
        const std::string message = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw std::runtime_error("cannot write " + temporary.string() + ": " + message);
    }
    for (const ZipEntry& e : entries) {
        zip_source_t* source = e.file.empty()
                                   ? zip_source_buffer(archive.archive, e.content.data(), e.content.size(), 0)
                                   : zip_source_file(archive.archive, e.file.string().c_str(), 0, -1);
        if (!source) zipFailure(archive.archive, e.name);
        const zip_int64_t index = zip_file_add(archive.archive, e.name.c_str(), source, ZIP_FL_ENC_UTF_8);
        if (index < 0) {
            zip_source_free(source);
            zipFailure(archive.archive, e.name);
        }
        const zip_uint32_t mode = 0100000u | (e.executable ? 0755u : 0644u); // a regular file
        if (zip_file_set_external_attributes(archive.archive, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX, mode << 16) < 0)
            zipFailure(archive.archive, e.name);
    }
    if (zip_close(archive.archive) < 0) {
        const std::string message = zip_strerror(archive.archive);
        std::error_code error;
        fs::remove(temporary, error);
        throw std::runtime_error("cannot write " + zip.string() + ": " + message);
    }
    archive.archive = nullptr;
    fs::rename(temporary, zip);
}

} // namespace raylab::grader
