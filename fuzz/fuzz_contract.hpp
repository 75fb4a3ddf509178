#pragma once
// The readers' contract, checked on every fuzz input: a reader returns or throws
// pound::InputError. Any other exception is a bug, reported to libFuzzer as a crash (abort) with
// the exception's message; crashes, hangs and sanitizer reports are libFuzzer's to catch.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/errors.hpp"

namespace pound::fuzz {

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

template <class Reader>
void expect_input_error_only(const char* what, Reader&& reader) {
  try {
    reader();
  } catch (const InputError&) {
    // A refused input: the contract holds.
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: uncaught %s: %s\n", what, typeid(error).name(), error.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "%s: uncaught exception of unknown type\n", what);
    std::abort();
  }
}

}  // namespace pound::fuzz
