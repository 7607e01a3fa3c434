#pragma once

namespace scanfilter {

// Each filter has a literal reference implementation of the paper's steps and
// a fast one that must give the same labels (tests/agreement_test.cpp).
enum class Implementation { kReference, kFast };

}  // namespace scanfilter
