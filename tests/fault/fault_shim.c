// LD_PRELOAD fault shim for the fault-injection suite (docs/reliability.md).
//
// It learns which file descriptors refer to files under PALPATE_FAULT_DIR (from open, openat, creat
// and fopen: the path the kernel resolved, read back from /proc/self/fd, so relative paths, dirfds
// and O_TMPFILE all count) and makes writes, fsyncs and closes on those descriptors fail as a sick
// disk would. stdout, stderr and every other file are left alone. It also makes pthread_create fail.
//
// Environment (all optional; unset means no fault of that kind):
//   PALPATE_FAULT_DIR=DIR                    files under DIR are the victims
//   PALPATE_FAULT_ENOSPC_AFTER_BYTES=N       after N bytes in total, writes fail with ENOSPC (the
//                                            write that crosses N writes what still fits: a full disk)
//   PALPATE_FAULT_EIO_AFTER_BYTES=N          the same with EIO
//   PALPATE_FAULT_SHORT_WRITES=1             each write writes at most half of what it is given (>= 1 byte)
//   PALPATE_FAULT_FSYNC_EIO=1                fsync and fdatasync fail with EIO
//   PALPATE_FAULT_CLOSE_EIO=1                close fails with EIO (after closing: POSIX leaves it closed)
//   PALPATE_FAULT_PTHREAD_CREATE_FAIL_AFTER=K  the (K+1)-th and later pthread_create return EAGAIN
//   PALPATE_FAULT_LOG=FILE                   one line per kind of fault injected ("enospc", "eio",
//                                            "short", "fsync", "close", "pthread"), so a test knows
//                                            that the fault was really met
//
// Plain C, no dependency but libc and libdl; every entry point is async-signal-safe enough for the
// paths it takes (no malloc after start-up), and thread-safe through atomics, since the recorder
// writes from its own thread.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#define FAULT_MAX_FDS 65536

static atomic_uchar gTracked[FAULT_MAX_FDS];
static atomic_llong gBytesWritten;
static atomic_int gThreadsCreated;
static atomic_int gLogged[8];

static int gConfigured;
static char gDir[4096];
static size_t gDirLength;
static long long gEnospcAfter = -1;
static long long gEioAfter = -1;
static int gShortWrites;
static int gFsyncEio;
static int gCloseEio;
static int gPthreadFailAfter = -1;
static char gLogPath[4096];

enum { LOG_ENOSPC, LOG_EIO, LOG_SHORT, LOG_FSYNC, LOG_CLOSE, LOG_PTHREAD };
static const char* const kLogNames[] = {"enospc", "eio", "short", "fsync", "close", "pthread"};

static long long envNumber(const char* name, long long fallback) {
    const char* text = getenv(name);
    if (!text || !*text) return fallback;
    return strtoll(text, NULL, 10);
}

static void configure(void) {
    if (gConfigured) return;
    const char* dir = getenv("PALPATE_FAULT_DIR");
    if (dir && *dir) {
        // The kernel's resolved path is compared, so the directory must be resolved too.
        if (!realpath(dir, gDir)) snprintf(gDir, sizeof gDir, "%s", dir);
        gDirLength = strlen(gDir);
        while (gDirLength > 1 && gDir[gDirLength - 1] == '/') gDir[--gDirLength] = '\0';
    }
    gEnospcAfter = envNumber("PALPATE_FAULT_ENOSPC_AFTER_BYTES", -1);
    gEioAfter = envNumber("PALPATE_FAULT_EIO_AFTER_BYTES", -1);
    gShortWrites = (int)envNumber("PALPATE_FAULT_SHORT_WRITES", 0);
    gFsyncEio = (int)envNumber("PALPATE_FAULT_FSYNC_EIO", 0);
    gCloseEio = (int)envNumber("PALPATE_FAULT_CLOSE_EIO", 0);
    gPthreadFailAfter = (int)envNumber("PALPATE_FAULT_PTHREAD_CREATE_FAIL_AFTER", -1);
    const char* log = getenv("PALPATE_FAULT_LOG");
    if (log) snprintf(gLogPath, sizeof gLogPath, "%s", log);
    gConfigured = 1;
}

__attribute__((constructor)) static void faultShimInit(void) { configure(); }

#define REAL(name, type)                                   \
    static type real_##name;                               \
    if (!real_##name) real_##name = (type)dlsym(RTLD_NEXT, #name)

static void logFault(int kind) {
    if (!gLogPath[0] || atomic_exchange(&gLogged[kind], 1)) return;
    typedef int (*OpenFn)(const char*, int, ...);
    typedef ssize_t (*WriteFn)(int, const void*, size_t);
    typedef int (*CloseFn)(int);
    REAL(open, OpenFn);
    REAL(write, WriteFn);
    REAL(close, CloseFn);
    const int fd = real_open(gLogPath, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) return;
    char line[32];
    const int n = snprintf(line, sizeof line, "%s\n", kLogNames[kind]);
    (void)!real_write(fd, line, (size_t)n);
    real_close(fd);
}

// Marks fd as a victim when the file it opened lies under PALPATE_FAULT_DIR, and forgets it
// otherwise (descriptor numbers are reused, also after closes this shim does not see).
static void noteOpened(int fd) {
    if (fd < 0 || fd >= FAULT_MAX_FDS) return;
    configure();
    int victim = 0;
    if (gDirLength > 0) {
        char link[64];
        char target[4096];
        snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
        const ssize_t n = readlink(link, target, sizeof target - 1);
        if (n > 0) {
            target[n] = '\0';
            victim = strncmp(target, gDir, gDirLength) == 0 &&
                     (target[gDirLength] == '/' || target[gDirLength] == '\0');
        }
    }
    atomic_store(&gTracked[fd], (unsigned char)victim);
}

static int isVictim(int fd) { return fd >= 0 && fd < FAULT_MAX_FDS && atomic_load(&gTracked[fd]); }

static int hasModeArgument(int flags) { return (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE; }

int open(const char* path, int flags, ...) {
    typedef int (*Fn)(const char*, int, ...);
    REAL(open, Fn);
    mode_t mode = 0;
    if (hasModeArgument(flags)) {
        va_list args;
        va_start(args, flags);
        mode = va_arg(args, mode_t);
        va_end(args);
    }
    const int fd = real_open(path, flags, mode);
    noteOpened(fd);
    return fd;
}

int open64(const char* path, int flags, ...) {
    typedef int (*Fn)(const char*, int, ...);
    REAL(open64, Fn);
    mode_t mode = 0;
    if (hasModeArgument(flags)) {
        va_list args;
        va_start(args, flags);
        mode = va_arg(args, mode_t);
        va_end(args);
    }
    const int fd = real_open64(path, flags, mode);
    noteOpened(fd);
    return fd;
}

int openat(int dirfd, const char* path, int flags, ...) {
    typedef int (*Fn)(int, const char*, int, ...);
    REAL(openat, Fn);
    mode_t mode = 0;
    if (hasModeArgument(flags)) {
        va_list args;
        va_start(args, flags);
        mode = va_arg(args, mode_t);
        va_end(args);
    }
    const int fd = real_openat(dirfd, path, flags, mode);
    noteOpened(fd);
    return fd;
}

int openat64(int dirfd, const char* path, int flags, ...) {
    typedef int (*Fn)(int, const char*, int, ...);
    REAL(openat64, Fn);
    mode_t mode = 0;
    if (hasModeArgument(flags)) {
        va_list args;
        va_start(args, flags);
        mode = va_arg(args, mode_t);
        va_end(args);
    }
    const int fd = real_openat64(dirfd, path, flags, mode);
    noteOpened(fd);
    return fd;
}

// _FORTIFY_SOURCE builds (Debian's Qt) call these when the flags are not a compile-time constant.
int __open_2(const char* path, int flags) {
    typedef int (*Fn)(const char*, int);
    REAL(__open_2, Fn);
    const int fd = real___open_2(path, flags);
    noteOpened(fd);
    return fd;
}

int __open64_2(const char* path, int flags) {
    typedef int (*Fn)(const char*, int);
    REAL(__open64_2, Fn);
    const int fd = real___open64_2(path, flags);
    noteOpened(fd);
    return fd;
}

int __openat_2(int dirfd, const char* path, int flags) {
    typedef int (*Fn)(int, const char*, int);
    REAL(__openat_2, Fn);
    const int fd = real___openat_2(dirfd, path, flags);
    noteOpened(fd);
    return fd;
}

int __openat64_2(int dirfd, const char* path, int flags) {
    typedef int (*Fn)(int, const char*, int);
    REAL(__openat64_2, Fn);
    const int fd = real___openat64_2(dirfd, path, flags);
    noteOpened(fd);
    return fd;
}

int creat(const char* path, mode_t mode) {
    typedef int (*Fn)(const char*, mode_t);
    REAL(creat, Fn);
    const int fd = real_creat(path, mode);
    noteOpened(fd);
    return fd;
}

int creat64(const char* path, mode_t mode) {
    typedef int (*Fn)(const char*, mode_t);
    REAL(creat64, Fn);
    const int fd = real_creat64(path, mode);
    noteOpened(fd);
    return fd;
}

// std::ofstream opens through fopen (glibc's internal open is not interposable) and then writes
// with write(2) on fileno(), so fopen is where its descriptor is learnt.
FILE* fopen(const char* path, const char* mode) {
    typedef FILE* (*Fn)(const char*, const char*);
    REAL(fopen, Fn);
    FILE* file = real_fopen(path, mode);
    if (file) noteOpened(fileno(file));
    return file;
}

FILE* fopen64(const char* path, const char* mode) {
    typedef FILE* (*Fn)(const char*, const char*);
    REAL(fopen64, Fn);
    FILE* file = real_fopen64(path, mode);
    if (file) noteOpened(fileno(file));
    return file;
}

// How many of `size` bytes a write on a victim may write: -1 with errno set when none.
static ssize_t allowedBytes(size_t size) {
    configure();
    if (size == 0) return 0;
    long long allowed = (long long)size;
    if (gShortWrites && allowed > 1) {
        allowed = allowed / 2;
        logFault(LOG_SHORT);
    }
    long long limit = -1;
    int error = 0;
    int kind = 0;
    if (gEnospcAfter >= 0) limit = gEnospcAfter, error = ENOSPC, kind = LOG_ENOSPC;
    if (gEioAfter >= 0 && (limit < 0 || gEioAfter < limit)) limit = gEioAfter, error = EIO, kind = LOG_EIO;
    // Reserve the bytes first so that two threads cannot both fill the last free byte.
    const long long before = atomic_fetch_add(&gBytesWritten, allowed);
    if (limit >= 0 && before + allowed > limit) {
        const long long granted = limit > before ? limit - before : 0;
        atomic_fetch_sub(&gBytesWritten, allowed - granted);
        logFault(kind);
        if (granted == 0) {
            errno = error;
            return -1;
        }
        return (ssize_t)granted;
    }
    return (ssize_t)allowed;
}

ssize_t write(int fd, const void* data, size_t size) {
    typedef ssize_t (*Fn)(int, const void*, size_t);
    REAL(write, Fn);
    if (!isVictim(fd)) return real_write(fd, data, size);
    const ssize_t allowed = allowedBytes(size);
    if (allowed < 0) return -1;
    return real_write(fd, data, (size_t)allowed);
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t offset) {
    typedef ssize_t (*Fn)(int, const void*, size_t, off_t);
    REAL(pwrite, Fn);
    if (!isVictim(fd)) return real_pwrite(fd, data, size, offset);
    const ssize_t allowed = allowedBytes(size);
    if (allowed < 0) return -1;
    return real_pwrite(fd, data, (size_t)allowed, offset);
}

ssize_t pwrite64(int fd, const void* data, size_t size, off64_t offset) {
    typedef ssize_t (*Fn)(int, const void*, size_t, off64_t);
    REAL(pwrite64, Fn);
    if (!isVictim(fd)) return real_pwrite64(fd, data, size, offset);
    const ssize_t allowed = allowedBytes(size);
    if (allowed < 0) return -1;
    return real_pwrite64(fd, data, (size_t)allowed, offset);
}

// A faulted writev writes only a prefix of the buffers, through write, as a short writev would.
ssize_t writev(int fd, const struct iovec* buffers, int count) {
    typedef ssize_t (*Fn)(int, const struct iovec*, int);
    REAL(writev, Fn);
    if (!isVictim(fd)) return real_writev(fd, buffers, count);
    size_t total = 0;
    for (int i = 0; i < count; ++i) total += buffers[i].iov_len;
    ssize_t allowed = allowedBytes(total);
    if (allowed < 0) return -1;
    typedef ssize_t (*WriteFn)(int, const void*, size_t);
    REAL(write, WriteFn);
    ssize_t done = 0;
    for (int i = 0; i < count && allowed > 0; ++i) {
        const size_t part = buffers[i].iov_len < (size_t)allowed ? buffers[i].iov_len : (size_t)allowed;
        const ssize_t n = real_write(fd, buffers[i].iov_base, part);
        if (n < 0) return done > 0 ? done : -1;
        done += n;
        allowed -= n;
        if ((size_t)n < part) break;
    }
    return done;
}

int fsync(int fd) {
    typedef int (*Fn)(int);
    REAL(fsync, Fn);
    configure();
    if (isVictim(fd) && gFsyncEio) {
        logFault(LOG_FSYNC);
        errno = EIO;
        return -1;
    }
    return real_fsync(fd);
}

int fdatasync(int fd) {
    typedef int (*Fn)(int);
    REAL(fdatasync, Fn);
    configure();
    if (isVictim(fd) && gFsyncEio) {
        logFault(LOG_FSYNC);
        errno = EIO;
        return -1;
    }
    return real_fdatasync(fd);
}

int close(int fd) {
    typedef int (*Fn)(int);
    REAL(close, Fn);
    configure();
    const int victim = isVictim(fd);
    if (fd >= 0 && fd < FAULT_MAX_FDS) atomic_store(&gTracked[fd], 0);
    const int result = real_close(fd);
    if (victim && gCloseEio && result == 0) {
        logFault(LOG_CLOSE);
        errno = EIO;
        return -1;
    }
    return result;
}

int fclose(FILE* file) {
    typedef int (*Fn)(FILE*);
    REAL(fclose, Fn);
    if (file) {
        const int fd = fileno(file);
        if (fd >= 0 && fd < FAULT_MAX_FDS) atomic_store(&gTracked[fd], 0);
    }
    return real_fclose(file);
}

int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg) {
    typedef int (*Fn)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);
    REAL(pthread_create, Fn);
    configure();
    if (gPthreadFailAfter >= 0 && atomic_fetch_add(&gThreadsCreated, 1) >= gPthreadFailAfter) {
        logFault(LOG_PTHREAD);
        return EAGAIN;
    }
    return real_pthread_create(thread, attr, start, arg);
}
