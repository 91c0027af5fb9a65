#pragma once
// One libFuzzer entry point around a reader of fuzz_targets.h: an InputError is the reader's
// answer to bad input; any other exception is reported and aborts, so libFuzzer keeps the input.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>
#include "core/error.h"

#define COLUMBA_FUZZ_TARGET(CALL)                                              \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {    \
    try {                                                                      \
      CALL;                                                                    \
    } catch (const columba::InputError&) {                                     \
    } catch (const std::exception& e) {                                        \
      std::fprintf(stdout, "unexpected %s: %s\n", typeid(e).name(), e.what()); \
      std::fflush(stdout);                                                     \
      std::abort();                                                            \
    }                                                                          \
    return 0;                                                                  \
  }
