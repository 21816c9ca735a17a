#pragma once
// Rows of equal length (one value per agent: a configuration, priorities, an order) appended and
// never moved: memory comes in chunks of about 4 MB, so a search holding a million rows neither
// copies them when it grows nor keeps a second copy while it does.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace cosim {

template <typename T>
class RowArena {
 public:
  explicit RowArena(std::size_t row_length)
      : row_length_(row_length == 0 ? 1 : row_length),
        rows_per_chunk_(
            std::max<std::size_t>(1, (std::size_t(4) << 20) / sizeof(T) / row_length_)) {}

  // A new row (uninitialised), and its index.
  std::size_t append() {
    if (size_ == chunks_.size() * rows_per_chunk_)
      chunks_.push_back(std::make_unique_for_overwrite<T[]>(rows_per_chunk_ * row_length_));
    return size_++;
  }
  T* row(std::size_t i) {
    return chunks_[i / rows_per_chunk_].get() + (i % rows_per_chunk_) * row_length_;
  }
  const T* row(std::size_t i) const {
    return chunks_[i / rows_per_chunk_].get() + (i % rows_per_chunk_) * row_length_;
  }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return chunks_.size() * rows_per_chunk_ * row_length_ * sizeof(T); }

 private:
  std::size_t row_length_, rows_per_chunk_;
  std::size_t size_ = 0;
  std::vector<std::unique_ptr<T[]>> chunks_;
};

}  // namespace cosim
