#pragma once
// Bad input refused where it stands: `make` (reading, building or loading a model) must throw an
// InputError at the JSON path `where` whose reason holds `phrase`.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"

namespace pound::testing {

template <class Make>
void expect_input_error(Make&& make, const std::string& where, const std::string& phrase) {
  try {
    make();
    ADD_FAILURE() << "accepted; expected " << phrase;
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), where) << error.what();
    EXPECT_NE(error.reason().find(phrase), std::string::npos) << error.what();
  }
}

}  // namespace pound::testing
