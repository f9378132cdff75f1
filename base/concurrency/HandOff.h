#pragma once
// A hand-off from one thread to another through a queue the thread sanitizer cannot see: Qt's
// event queue (a queued QMetaObject::invokeMethod, a queued signal such as QThread::finished). Qt
// is not built with the sanitizer, so the lock that orders the post before the delivery is
// invisible to it, and every result a worker hands to the GUI thread would be reported as a race.
// The sender calls handOffRelease() just before posting and the receiver handOffAcquire() first
// thing: under ThreadSanitizer these tell it what Qt's lock does; elsewhere they compile to
// nothing. They order only what really is ordered by the post, so a race of our own (a worker
// touching the data after it posted it) is still reported (docs/reliability.md, "Sanitizers").

#if defined(__SANITIZE_THREAD__)
#define PALPATE_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PALPATE_TSAN 1
#endif
#endif

#if defined(PALPATE_TSAN)
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

namespace palpate {

namespace detail {
/// One token for every queue, as Qt's posted-event lock is one per receiving thread.
inline char gHandOffToken;
}  // namespace detail

/// The sender, just before it posts.
inline void handOffRelease() {
#if defined(PALPATE_TSAN)
    __tsan_release(&detail::gHandOffToken);
#endif
}

/// The receiver, before it reads what was handed off (the posted functor's captures included).
inline void handOffAcquire() {
#if defined(PALPATE_TSAN)
    __tsan_acquire(&detail::gHandOffToken);
#endif
}

}  // namespace palpate
