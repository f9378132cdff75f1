// The lock-free primitives between threads (base/concurrency): each one's contract alone, and a
// stress test with a real producer and consumer thread that checks every item arrives once, in
// order, whole. Under the tsan preset the stress tests are the data-race check of the primitive.

#include "base/concurrency/SeqLock.h"
#include "base/concurrency/SpscQueue.h"
#include "base/concurrency/SpscRing.h"
#include "base/concurrency/TripleBuffer.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>

namespace palpate {
namespace {

/// An item whose fields must always agree: a torn copy shows as a mismatch.
struct Item {
    std::uint64_t sequence = 0;
    std::uint64_t check = ~std::uint64_t(0);  ///< ~sequence (a default item is whole too)
    std::array<std::uint64_t, 6> body{};  ///< each = sequence * (i + 1)

    static Item of(std::uint64_t n) {
        Item item;
        item.sequence = n;
        item.check = ~n;
        for (std::size_t i = 0; i < item.body.size(); ++i) item.body[i] = n * (i + 1);
        return item;
    }
    bool whole() const {
        if (check != ~sequence) return false;
        for (std::size_t i = 0; i < body.size(); ++i)
            if (body[i] != sequence * (i + 1)) return false;
        return true;
    }
};

constexpr std::uint64_t kStressItems = 200000;

// ---- SpscQueue --------------------------------------------------------------------------------

TEST(SpscQueue, KeepsOrderRefusesWhenFullAndPopsNothingWhenEmpty) {
    SpscQueue<int, 4> q;
    int out = -1;
    EXPECT_TRUE(q.empty());
    EXPECT_FALSE(q.pop(out));
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(q.push(i)) << i;
    EXPECT_FALSE(q.push(99)) << "a full queue refuses";
    for (int i = 0; i < 4; ++i) {
        ASSERT_TRUE(q.pop(out));
        EXPECT_EQ(out, i);
    }
    EXPECT_FALSE(q.pop(out));
    EXPECT_TRUE(q.empty());
}

TEST(SpscQueue, WrapsAroundItsStorageManyTimes) {
    SpscQueue<std::uint64_t, 8> q;
    std::uint64_t next = 0, expected = 0, out = 0;
    for (int round = 0; round < 1000; ++round) {
        for (int i = 0; i < 5; ++i) ASSERT_TRUE(q.push(next++));
        for (int i = 0; i < 5; ++i) {
            ASSERT_TRUE(q.pop(out));
            ASSERT_EQ(out, expected++);
        }
    }
}

TEST(SpscQueue, StressOneProducerOneConsumerEveryItemOnceInOrderWhole) {
    SpscQueue<Item, 64> q;
    std::thread producer([&] {
        for (std::uint64_t n = 0; n < kStressItems;)
            if (q.push(Item::of(n))) ++n;
    });
    std::uint64_t expected = 0, torn = 0, outOfOrder = 0;
    Item item;
    while (expected < kStressItems) {
        if (!q.pop(item)) continue;
        if (!item.whole()) ++torn;
        if (item.sequence != expected) ++outOfOrder;
        expected = item.sequence + 1;
    }
    producer.join();
    EXPECT_EQ(torn, 0u);
    EXPECT_EQ(outOfOrder, 0u);
    EXPECT_FALSE(q.pop(item)) << "nothing more than was pushed";
}

// ---- SpscRing ---------------------------------------------------------------------------------

TEST(SpscRing, CapacityIsAPowerOfTwoAtLeastTheOneAskedFor) {
    EXPECT_EQ(SpscRing<int>(0).capacity(), 2u);
    EXPECT_EQ(SpscRing<int>(2).capacity(), 2u);
    EXPECT_EQ(SpscRing<int>(3).capacity(), 4u);
    EXPECT_EQ(SpscRing<int>(1000).capacity(), 1024u);
}

TEST(SpscRing, KeepsOrderCountsAndRefusesWhenFull) {
    SpscRing<int> ring(4);
    for (int i = 0; i < 4; ++i) ASSERT_TRUE(ring.push(i));
    EXPECT_EQ(ring.size(), 4u);
    EXPECT_FALSE(ring.push(4));
    int out = -1;
    ASSERT_TRUE(ring.pop(out));
    EXPECT_EQ(out, 0);
    EXPECT_EQ(ring.size(), 3u);
    EXPECT_TRUE(ring.push(4)) << "room again after a pop";
    for (int i = 1; i <= 4; ++i) {
        ASSERT_TRUE(ring.pop(out));
        EXPECT_EQ(out, i);
    }
    EXPECT_FALSE(ring.pop(out));
    EXPECT_EQ(ring.size(), 0u);
}

TEST(SpscRing, StressOneProducerOneConsumerEveryItemOnceInOrderWhole) {
    SpscRing<Item> ring(100);
    std::thread producer([&] {
        for (std::uint64_t n = 0; n < kStressItems;)
            if (ring.push(Item::of(n))) ++n;
    });
    std::uint64_t expected = 0, torn = 0, outOfOrder = 0;
    Item item;
    while (expected < kStressItems) {
        if (!ring.pop(item)) continue;
        if (!item.whole()) ++torn;
        if (item.sequence != expected) ++outOfOrder;
        expected = item.sequence + 1;
    }
    producer.join();
    EXPECT_EQ(torn, 0u);
    EXPECT_EQ(outOfOrder, 0u);
    EXPECT_EQ(ring.size(), 0u);
}

// ---- TripleBuffer -----------------------------------------------------------------------------

TEST(TripleBuffer, TheReaderGetsTheNewestPublishAndKeepsItUntilTheNext) {
    TripleBuffer<Item> buffer;
    EXPECT_EQ(buffer.newest().sequence, 0u) << "before any publish: a default value";
    for (std::uint64_t n = 1; n <= 3; ++n) {
        buffer.back() = Item::of(n);
        buffer.publish();
    }
    const Item& read = buffer.newest();
    EXPECT_EQ(read.sequence, 3u) << "the newest, not the first, of three publishes";
    EXPECT_TRUE(read.whole());
    EXPECT_EQ(buffer.newest().sequence, 3u) << "nothing new: the same value again";
    buffer.back() = Item::of(4);  // written, not yet published
    EXPECT_EQ(buffer.newest().sequence, 3u);
    buffer.publish();
    EXPECT_EQ(buffer.newest().sequence, 4u);
}

TEST(TripleBuffer, TheWriterNeverWritesIntoTheBufferTheReaderHolds) {
    TripleBuffer<Item> buffer;
    buffer.back() = Item::of(1);
    buffer.publish();
    const Item* held = &buffer.newest();
    for (std::uint64_t n = 2; n < 20; ++n) {
        EXPECT_NE(&buffer.back(), held) << n;
        buffer.back() = Item::of(n);
        buffer.publish();
    }
    EXPECT_EQ(held->sequence, 1u) << "the value the reader holds is unchanged";
}

TEST(TripleBuffer, StressWriterAndReaderNeverTornNeverBackwards) {
    TripleBuffer<Item> buffer;
    std::atomic<bool> done{false};
    std::thread writer([&] {
        for (std::uint64_t n = 1; n <= kStressItems; ++n) {
            buffer.back() = Item::of(n);
            buffer.publish();
        }
        done.store(true, std::memory_order_release);
    });
    std::uint64_t last = 0, torn = 0, backwards = 0, reads = 0;
    for (;;) {
        const bool finished = done.load(std::memory_order_acquire);
        const Item& item = buffer.newest();
        ++reads;
        if (!item.whole()) ++torn;
        if (item.sequence < last) ++backwards;
        last = item.sequence;
        if (finished) break;
    }
    writer.join();
    EXPECT_EQ(torn, 0u);
    EXPECT_EQ(backwards, 0u);
    EXPECT_EQ(buffer.newest().sequence, kStressItems) << "the last publish is seen";
    EXPECT_GT(reads, 0u);
}

// ---- SeqLock ----------------------------------------------------------------------------------

TEST(SeqLock, LoadsWhatWasStoredAndStartsFromItsInitialValue) {
    SeqLock<Item> lock(Item::of(7));
    EXPECT_EQ(lock.load().sequence, 7u);
    lock.store(Item::of(8));
    Item out;
    ASSERT_TRUE(lock.tryLoad(out));
    EXPECT_EQ(out.sequence, 8u);
    EXPECT_TRUE(out.whole());
}

TEST(SeqLock, StressWriterAndReaderNeverTornNeverBackwards) {
    SeqLock<Item> lock;
    std::atomic<bool> done{false};
    std::thread writer([&] {
        for (std::uint64_t n = 1; n <= kStressItems; ++n) lock.store(Item::of(n));
        done.store(true, std::memory_order_release);
    });
    std::uint64_t last = 0, torn = 0, backwards = 0;
    for (;;) {
        const bool finished = done.load(std::memory_order_acquire);
        const Item item = lock.load();
        if (!item.whole()) ++torn;
        if (item.sequence < last) ++backwards;
        last = item.sequence;
        if (finished) break;
    }
    writer.join();
    EXPECT_EQ(torn, 0u);
    EXPECT_EQ(backwards, 0u);
    EXPECT_EQ(lock.load().sequence, kStressItems);
}

}  // namespace
}  // namespace palpate
