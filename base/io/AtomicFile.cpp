#include "base/io/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace palpate {

namespace {

std::string reason(int e) { return std::strerror(e); }

/// "DIR/NAME.tmp-PID-N.EXT": unique per process and call, so two writers of one target never share
/// a temporary; the extension stays last for writers that choose the format by it.
std::string temporaryNameFor(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    namespace fs = std::filesystem;
    const fs::path p(path);
    const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    return (p.parent_path() / (p.stem().string() + tag + p.extension().string())).string();
}

/// "" when `path` is absent or a regular file (which the rename may replace); else why not: a
/// rename over /dev/full or a FIFO would replace the special file itself.
std::string targetProblem(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return {};
    const char* type = S_ISDIR(st.st_mode)                          ? "a directory"
                       : S_ISFIFO(st.st_mode)                       ? "a FIFO"
                       : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                    : "a special file";
    return path + ": is " + type + ", not a file that can be written";
}

/// Creates the temporary exclusively (O_EXCL: never an existing file), trying another name if one
/// is taken. -1 with errno set on failure.
int createTemporary(const std::string& path, std::string& temporary) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary = temporaryNameFor(path);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            // The replaced file keeps its permissions (a private preset stays private).
            struct stat st {};
            if (::stat(path.c_str(), &st) == 0) ::fchmod(fd, st.st_mode & 07777);
            return fd;
        }
        if (errno != EEXIST) return fd;
    }
    return -1;
}

/// Writes all of `text`, across short writes and interruptions. errno set on failure.
bool writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

/// fsyncs the temporary, renames it over `path` and fsyncs the folder, so the new file is on disk
/// under its name when this returns "". Removes the temporary on failure.
std::string commitTemporary(const std::string& path, const std::string& temporary, int fd) {
    if (::fsync(fd) != 0) {
        const int e = errno;
        ::close(fd);
        ::unlink(temporary.c_str());
        return path + ": writing failed: " + reason(e);
    }
    if (::close(fd) != 0) {
        const int e = errno;
        ::unlink(temporary.c_str());
        return path + ": writing failed: " + reason(e);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const int e = errno;
        ::unlink(temporary.c_str());
        return path + ": cannot be replaced: " + reason(e);
    }
    const std::string folder = std::filesystem::path(path).parent_path().string();
    const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);  // best effort: some file systems refuse a folder's fsync
        ::close(dir);
    }
    return {};
}

}  // namespace

std::string writeFileAtomically(const std::string& path, const std::string& text) {
    if (std::string problem = targetProblem(path); !problem.empty()) return problem;
    std::string temporary;
    const int fd = createTemporary(path, temporary);
    if (fd < 0) return path + ": cannot be written: " + reason(errno);
    if (!writeAll(fd, text.data(), text.size())) {
        const int e = errno;
        ::close(fd);
        ::unlink(temporary.c_str());
        return path + ": writing failed: " + reason(e);
    }
    return commitTemporary(path, temporary, fd);
}

std::string writeFileAtomicallyVia(const std::string& path,
                                   const std::function<std::string(const std::string& temporaryPath)>& write) {
    if (std::string problem = targetProblem(path); !problem.empty()) return problem;
    std::string temporary;
    int fd = createTemporary(path, temporary);
    if (fd < 0) return path + ": cannot be written: " + reason(errno);
    ::close(fd);
    if (std::string problem = write(temporary); !problem.empty()) {
        ::unlink(temporary.c_str());
        return path + ": writing failed: " + problem;
    }
    // Opened again to fsync what the writer wrote (a write error it missed shows here too).
    fd = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
        const int e = errno;
        ::unlink(temporary.c_str());
        return path + ": writing failed: " + reason(e);
    }
    return commitTemporary(path, temporary, fd);
}

}  // namespace palpate
