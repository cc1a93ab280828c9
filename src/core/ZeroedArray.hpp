#pragma once
// A fixed-size array that starts all zeros without writing them. Its storage comes from calloc,
// which for a large block maps fresh pages from the kernel: they read as zeros and cost nothing
// until first touched (first written where a read maps the kernel's shared zero page; on some
// kernels, 6.18 among them, a read takes a page of its own). An array of flags that a run
// touches in few places (the broken bonds of a fracture run) then occupies only the pages it
// reaches, where a std::vector would write every byte up front. That first write of every page is
// what set-up pays for memory: on the test machine, beyond the first ~1.3-2.1 GB a process touches,
// about 13 us per 4 KiB page, so zeroing the 249 MB of a 128^3 run's broken-bond flags could cost
// ~0.8 s (bench/RESULTS.md).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace peridot {

template <typename T>
class ZeroedArray {
  static_assert(std::is_trivial_v<T>, "all-zero bytes must be a value of T");

 public:
  ZeroedArray() = default;
  explicit ZeroedArray(std::size_t size) : size_(size) {
    if (size == 0) return;
    data_ = static_cast<T*>(std::calloc(size, sizeof(T)));
    if (!data_) throw std::bad_alloc();
  }
  ZeroedArray(const ZeroedArray&) = delete;
  ZeroedArray& operator=(const ZeroedArray&) = delete;
  ZeroedArray(ZeroedArray&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  ZeroedArray& operator=(ZeroedArray&& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    return *this;
  }
  ~ZeroedArray() { std::free(data_); }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace peridot
