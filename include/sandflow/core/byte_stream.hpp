#pragma once
// The raw state of the kernel's parts, written and read back bit for bit (the
// checkpoint's payload, src/io/checkpoint.cpp). Values go in as their bytes
// (little-endian machines only, which the checkpoint's header checks); every
// read is bounds-checked and a short or inconsistent payload throws sf::Error
// "FORMAT ..." naming what was being read.
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "sandflow/core/error.hpp"

namespace sf {

class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    putRaw(&value, sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(std::uint64_t(values.size()));
    putRaw(values.data(), values.size() * sizeof(T));
  }
  void put(bool value) { put(std::uint8_t(value)); }
  void put(const std::optional<double>& value) { put(value.has_value()), put(value.value_or(0.0)); }
  void put(const std::string& text) {
    put(std::uint64_t(text.size()));
    putRaw(text.data(), text.size());
  }
  void putRaw(const void* data, std::size_t bytes) {
    if (bytes == 0) return;
    const std::size_t at = bytes_.size();
    bytes_.resize(at + bytes);
    std::memcpy(bytes_.data() + at, data, bytes);
  }
  // A short name before each part: a reader that lost its place says where.
  void tag(const char (&name)[5]) { putRaw(name, 4); }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class ByteReader {
 public:
  ByteReader(const char* data, std::size_t size, int version)
      : version(version), data_(data), size_(size) {}
  const int version;  // of the format that wrote the bytes: what a part holds may vary with it

  template <class T>
  T get(const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    getRaw(&value, sizeof(T), what);
    return value;
  }
  template <class T>
  void get(T& value, const char* what) {
    value = get<T>(what);
  }
  // Booleans as one byte, 0 or 1: any other byte is refused (not loaded as bool).
  bool getBool(const char* what) {
    const auto v = get<std::uint8_t>(what);
    if (v > 1) fail(std::string("it holds a bad flag in ") + what);
    return v == 1;
  }
  void get(std::optional<double>& value, const char* what) {
    const bool set = getBool(what);
    const auto v = get<double>(what);
    value = set ? std::optional<double>(v) : std::nullopt;
  }
  template <class T>
  void get(std::vector<T>& values, const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    values.resize(count(sizeof(T), what));
    getRaw(values.data(), values.size() * sizeof(T), what);
  }
  void get(std::string& text, const char* what) {
    text.resize(count(1, what));
    getRaw(text.data(), text.size(), what);
  }
  void getRaw(void* out, std::size_t bytes, const char* what) {
    if (bytes > size_ - at_) fail(std::string("it ends inside ") + what);
    if (bytes == 0) return;  // an empty vector's data() may be null
    std::memcpy(out, data_ + at_, bytes);
    at_ += bytes;
  }
  // Passes over bytes an older format holds that nothing reads now.
  void skip(std::size_t bytes, const char* what) {
    if (bytes > size_ - at_) fail(std::string("it ends inside ") + what);
    at_ += bytes;
  }
  // A count of items of `itemBytes` each: one that cannot fit in what is left
  // is refused before anything is allocated.
  std::size_t count(std::size_t itemBytes, const char* what) {
    const auto n = get<std::uint64_t>(what);
    if (itemBytes > 0 && n > (size_ - at_) / itemBytes)
      fail(std::string("it claims ") + std::to_string(n) + " items of " + what +
           ", more than it holds");
    return std::size_t(n);
  }
  void expectTag(const char (&name)[5]) {
    char got[4];
    getRaw(got, 4, name);
    if (std::memcmp(got, name, 4) != 0) fail(std::string("the part \"") + name + "\" is missing");
  }
  std::size_t left() const { return size_ - at_; }
  [[noreturn]] static void fail(const std::string& why) { throw Error("FORMAT CHECKPOINT", why); }

 private:
  const char* data_;
  std::size_t size_, at_ = 0;
};

}  // namespace sf
