#pragma once
// The one bounded reader of input files (docs/conventions.md, "Reading input files"): a path is
// opened without blocking (a FIFO never hangs the caller), the opened descriptor is checked to be
// a regular file, and its size against the format's limit before a byte is read, so a device, a
// directory or a 2 GB file is refused at once with a message that names the path.

#include "base/io/FileLimits.h"

#include <cstdint>
#include <optional>
#include <string>

namespace palpate {

/// An opened regular input file; owns its descriptor (closed on destruction).
class InputFd {
public:
    InputFd() = default;
    InputFd(int fd, std::uint64_t sizeBytes) : mFd(fd), mSizeBytes(sizeBytes) {}
    InputFd(InputFd&& other) noexcept;
    InputFd& operator=(InputFd&& other) noexcept;
    InputFd(const InputFd&) = delete;
    InputFd& operator=(const InputFd&) = delete;
    ~InputFd();

    int fd() const { return mFd; }
    /// The size fstat gave when the file was opened.
    std::uint64_t sizeBytes() const { return mSizeBytes; }
    /// Gives the descriptor to the caller (who closes it).
    int release();

private:
    int mFd = -1;
    std::uint64_t mSizeBytes = 0;
};

/// Opens `path` for reading (O_RDONLY | O_NONBLOCK | O_CLOEXEC; the descriptor is set back to
/// blocking once it is known to be a regular file). Refuses what is not a regular file ("is a FIFO,
/// not a preset file", "is a device", "is a directory") and a file larger than kind.maxBytes
/// ("2147483648 bytes, more than the 1 MiB a preset file may hold"). nullopt with `error` = "PATH:
/// problem" otherwise.
std::optional<InputFd> openInputFile(const std::string& path, const InputKind& kind, std::string& error);

/// The same checks for a reader that opens the path itself (std::ifstream, OpenMesh): "" when
/// `path` is a regular file within kind.maxBytes, else "PATH: problem". The file is opened and
/// closed again; a reader that can take a descriptor should use openInputFile instead.
std::string checkInputFile(const std::string& path, const InputKind& kind);

/// The whole file, read through openInputFile: at most kind.maxBytes + 1 bytes are read, so a file
/// that grows while it is read is refused too; a read error is reported with its reason.
std::optional<std::string> readInputFile(const std::string& path, const InputKind& kind, std::string& error);

/// "" when `sizeBytes` fits the format's limit, else "N bytes, more than the 1 MiB a preset file may
/// hold": the one wording of the limit, for the reader and for text that did not come from a file.
std::string sizeLimitProblem(std::uint64_t sizeBytes, const InputKind& kind);

/// "1 MiB", "4 KiB", "1000 bytes": a limit as the messages say it.
std::string describeByteCount(std::uint64_t bytes);

}  // namespace palpate
