#include "base/io/InputFile.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace palpate {

InputFd::InputFd(InputFd&& other) noexcept : mFd(other.mFd), mSizeBytes(other.mSizeBytes) { other.mFd = -1; }

InputFd& InputFd::operator=(InputFd&& other) noexcept {
    if (this != &other) {
        if (mFd >= 0) ::close(mFd);
        mFd = other.mFd;
        mSizeBytes = other.mSizeBytes;
        other.mFd = -1;
    }
    return *this;
}

InputFd::~InputFd() {
    if (mFd >= 0) ::close(mFd);
}

int InputFd::release() {
    const int fd = mFd;
    mFd = -1;
    return fd;
}

std::string sizeLimitProblem(std::uint64_t sizeBytes, const InputKind& kind) {
    if (sizeBytes <= kind.maxBytes) return "";
    return std::to_string(sizeBytes) + " bytes, more than the " + describeByteCount(kind.maxBytes) + " " + kind.name +
           " may hold";
}

std::string describeByteCount(std::uint64_t bytes) {
    if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
    if (bytes >= kKiB && bytes % kKiB == 0) return std::to_string(bytes / kKiB) + " KiB";
    return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
}

namespace {

/// What a file that is not a regular file is, for "is a FIFO, not a preset file".
const char* fileTypeName(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
}

}  // namespace

std::optional<InputFd> openInputFile(const std::string& path, const InputKind& kind, std::string& error) {
    // O_NONBLOCK: opening a FIFO with no writer (or a serial device) would otherwise block here,
    // before fstat could tell what it is.
    int fd = -1;
    do {
        fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) {
        const int e = errno;
        if (e == ENOENT) error = path + ": no such file";
        else error = path + ": cannot be opened for reading: " + std::strerror(e);
        return std::nullopt;
    }
    InputFd file(fd, 0);
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        error = path + ": cannot be examined: " + std::strerror(errno);
        return std::nullopt;
    }
    if (!S_ISREG(st.st_mode)) {
        error = path + ": is " + fileTypeName(st.st_mode) + ", not " + kind.name;
        return std::nullopt;
    }
    const std::uint64_t size = std::uint64_t(st.st_size);
    if (size > kind.maxBytes) {
        error = path + ": " + sizeLimitProblem(size, kind);
        return std::nullopt;
    }
    // A regular file never blocks; reads are ordinary again.
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return InputFd(file.release(), size);
}

std::string checkInputFile(const std::string& path, const InputKind& kind) {
    std::string error;
    if (!openInputFile(path, kind, error)) return error;
    return {};
}

std::optional<std::string> readInputFile(const std::string& path, const InputKind& kind, std::string& error) {
    std::optional<InputFd> file = openInputFile(path, kind, error);
    if (!file) return std::nullopt;
    std::string bytes;
    bytes.resize(std::size_t(file->sizeBytes()));
    std::size_t used = 0;
    // Read up to one byte beyond the limit: a file that grew past it since fstat is refused.
    const std::size_t most = std::size_t(kind.maxBytes) + 1;
    for (;;) {
        if (used == bytes.size()) {
            if (bytes.size() >= most) break;
            bytes.resize(std::min(most, std::max<std::size_t>(bytes.size() * 2, 4096)));
        }
        const ssize_t n = ::read(file->fd(), bytes.data() + used, bytes.size() - used);
        if (n < 0) {
            if (errno == EINTR) continue;
            error = path + ": cannot be read: " + std::strerror(errno);
            return std::nullopt;
        }
        if (n == 0) break;
        used += std::size_t(n);
    }
    if (used > kind.maxBytes) {
        error = path + ": grew past the " + describeByteCount(kind.maxBytes) + " " + kind.name +
                " may hold while it was read";
        return std::nullopt;
    }
    bytes.resize(used);
    return bytes;
}

}  // namespace palpate
