// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace e2d::physics::detail {

/// A contiguous growable array of trivially copyable slots whose growth copies little. Small
/// arrays (up to 256 KiB) live on the heap and grow with std::realloc(); past that, on Linux, the
/// block is mapped with mmap() and grown with mremap(), which moves the pages (no copy, no
/// second page fault for what was written; elsewhere realloc() throughout). The World's body
/// and shape slots live in these: creating 100 000 bodies one by one into std::vectors spent a
/// third of its time copying the arrays on growth and in page faults of the memory they were
/// copied into, and a segmented array (no copies either) made every index a few instructions
/// dearer, which cost the step 10 %. Small worlds stay on the heap because fresh mappings fault
/// every page again where freed heap memory is reused. Indexing is a vector's. Move-only;
/// emplace_back() value-initialises the new element. Growth moves the elements (references do
/// not survive it, as with std::vector).
template <class T>
class SlotArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
    static_assert(alignof(T) <= alignof(std::max_align_t));

public:
    SlotArray() = default;
    ~SlotArray() { release(); }
    SlotArray(SlotArray&& other) noexcept
        : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
          capacity_(std::exchange(other.capacity_, 0)), bytes_(std::exchange(other.bytes_, 0)),
          mapped_(std::exchange(other.mapped_, false)) {}
    SlotArray& operator=(SlotArray&& other) noexcept {
        if (this != &other) {
            release();
            data_ = std::exchange(other.data_, nullptr);
            size_ = std::exchange(other.size_, 0);
            capacity_ = std::exchange(other.capacity_, 0);
            bytes_ = std::exchange(other.bytes_, 0);
            mapped_ = std::exchange(other.mapped_, false);
        }
        return *this;
    }
    SlotArray(const SlotArray&) = delete;
    SlotArray& operator=(const SlotArray&) = delete;

    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] std::size_t capacity() const { return capacity_; }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    /// The first slot (null while the array has never held one).
    [[nodiscard]] T* data() { return data_; }
    [[nodiscard]] const T* data() const { return data_; }

    /// Room for `capacity` elements. Throws std::bad_alloc; the array is unchanged then.
    void reserve(std::size_t capacity) {
        if (capacity > capacity_) {
            grow(capacity);
        }
    }
    /// Appends a value-initialised element (geometric growth). Throws std::bad_alloc; the array
    /// is unchanged then.
    T& emplace_back() {
        if (size_ == capacity_) {
            // Fourfold on the heap (fewer copies of a small block), twofold once mapped (no
            // copies; untouched pages of a mapping cost nothing).
            grow(capacity_ == 0 ? 64 : (mapped_ ? 2 : 4) * capacity_);
        }
        T* slot = ::new (static_cast<void*>(data_ + size_)) T{};
        ++size_;
        return *slot;
    }

private:
    static constexpr std::size_t kPage = 4096;
    static constexpr std::size_t kMapThreshold = std::size_t{1} << 18;

    void grow(std::size_t capacity) {
        if (capacity > (static_cast<std::size_t>(-1) - kPage) / sizeof(T)) {
            throw std::bad_alloc();
        }
        std::size_t bytes = capacity * sizeof(T);
#if defined(__linux__)
        if (bytes > kMapThreshold) {
            // Whole pages: the mapping's tail is usable capacity.
            bytes = (bytes + kPage - 1) / kPage * kPage;
            void* grown = mapped_ ? ::mremap(data_, bytes_, bytes, MREMAP_MAYMOVE)
                                  : ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                                           MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (grown == MAP_FAILED) {
                throw std::bad_alloc(); // the old block is unchanged
            }
            if (!mapped_) {
                // Leaving the heap: the one copy, of at most kMapThreshold bytes.
                if (size_ > 0) {
                    std::memcpy(grown, static_cast<const void*>(data_), size_ * sizeof(T));
                }
                std::free(data_);
                mapped_ = true;
            }
            data_ = static_cast<T*>(grown);
            bytes_ = bytes;
            capacity_ = bytes / sizeof(T);
            return;
        }
#endif
        void* grown = std::realloc(data_, bytes == 0 ? sizeof(T) : bytes);
        if (grown == nullptr) {
            throw std::bad_alloc(); // the old block is unchanged
        }
        data_ = static_cast<T*>(grown);
        bytes_ = bytes;
        capacity_ = capacity == 0 ? 1 : capacity;
    }
    void release() {
#if defined(__linux__)
        if (mapped_) {
            ::munmap(data_, bytes_);
        } else {
            std::free(data_);
        }
#else
        std::free(data_);
#endif
        data_ = nullptr;
        size_ = 0;
        capacity_ = 0;
        bytes_ = 0;
        mapped_ = false;
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
    std::size_t bytes_ = 0;
    bool mapped_ = false; // data_ is an mmap()ed block of bytes_, else a malloc()ed one
};

} // namespace e2d::physics::detail
