// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

namespace e2d::physics::detail {

/// A growable array of trivially copyable slots that never moves them: it grows by adding
/// segments, each twice as large as the one before (64, 128, 256, ... elements), so growing
/// copies nothing and every page is touched once. The World's body and shape slots live in
/// these: creating 100 000 bodies one by one into std::vectors spent a third of its time in
/// copying the arrays on growth and in page faults of the memory they were copied into.
/// Indexing costs a bit_width and one more load than a vector's. Move-only; emplace_back()
/// value-initialises the new element; references stay valid until the array is destroyed.
template <class T>
class SlotArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    SlotArray() = default;
    ~SlotArray() { release(); }
    SlotArray(SlotArray&& other) noexcept
        : segments_(std::exchange(other.segments_, {})), size_(std::exchange(other.size_, 0)),
          capacity_(std::exchange(other.capacity_, 0)),
          segmentCount_(std::exchange(other.segmentCount_, 0)) {}
    SlotArray& operator=(SlotArray&& other) noexcept {
        if (this != &other) {
            release();
            segments_ = std::exchange(other.segments_, {});
            size_ = std::exchange(other.size_, 0);
            capacity_ = std::exchange(other.capacity_, 0);
            segmentCount_ = std::exchange(other.segmentCount_, 0);
        }
        return *this;
    }
    SlotArray(const SlotArray&) = delete;
    SlotArray& operator=(const SlotArray&) = delete;

    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] std::size_t capacity() const { return capacity_; }
    [[nodiscard]] bool empty() const { return size_ == 0; }

    T& operator[](std::size_t i) { return *locate(i); }
    const T& operator[](std::size_t i) const { return *locate(i); }

    /// Room for `capacity` elements without allocating. Throws std::bad_alloc; the array is
    /// unchanged then (segments added before the failure are kept as capacity).
    void reserve(std::size_t capacity) {
        while (capacity_ < capacity) {
            addSegment();
        }
    }
    /// Appends a value-initialised element. Throws std::bad_alloc; the array is unchanged then.
    T& emplace_back() {
        if (size_ == capacity_) {
            addSegment();
        }
        T* slot = ::new (static_cast<void*>(locate(size_))) T{};
        ++size_;
        return *slot;
    }

private:
    static constexpr int kFirstBits = 6; // the first segment holds 64 elements
    static constexpr int kMaxSegments = 40;

    // Segment s holds indices [64 (2^s - 1), 64 (2^(s+1) - 1)).
    T* locate(std::size_t i) const {
        const std::size_t q = (i >> kFirstBits) + 1;
        const int s = std::bit_width(q) - 1;
        const std::size_t base = (std::size_t{1} << (s + kFirstBits)) - (std::size_t{1} << kFirstBits);
        return segments_[static_cast<std::size_t>(s)] + (i - base);
    }
    void addSegment() {
        if (segmentCount_ == kMaxSegments) {
            throw std::bad_alloc();
        }
        const std::size_t count = std::size_t{1} << (segmentCount_ + kFirstBits);
        // Raw storage: pages are touched only when elements are constructed in them.
        void* memory = ::operator new(count * sizeof(T), std::align_val_t{alignof(T)});
        segments_[static_cast<std::size_t>(segmentCount_)] = static_cast<T*>(memory);
        ++segmentCount_;
        capacity_ += count;
    }
    void release() {
        for (int s = 0; s < segmentCount_; ++s) {
            ::operator delete(segments_[static_cast<std::size_t>(s)], std::align_val_t{alignof(T)});
        }
        segmentCount_ = 0;
        size_ = 0;
        capacity_ = 0;
    }

    std::array<T*, kMaxSegments> segments_{};
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
    int segmentCount_ = 0;
};

} // namespace e2d::physics::detail
