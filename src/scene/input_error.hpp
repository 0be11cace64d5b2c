#pragma once
// util/error.hpp for the scene loaders. GCC 12 at -O3 reports a false -Wrestrict inside
// InputError::format's string concatenation (GCC bug 105329) in every file that throws it; the
// warning is silenced here, for that header only, until error.hpp builds its message with append.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wrestrict"
#endif
#include "util/error.hpp"
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
