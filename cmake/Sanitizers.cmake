# GEOFLOW_SANITIZE: a sanitizer build of everything (libraries, programs, tests), e.g.
#   cmake -S . -B build-asan -DGEOFLOW_SANITIZE=address,undefined
# adds -fsanitize=<list> -fsanitize=float-cast-overflow (UBSan leaves it out of "undefined") and makes
# every report fatal (-fno-sanitize-recover=all), so a finding fails the test that triggered it.
# Applied to the whole build on purpose: a sanitizer must see every object, tests included.
set(GEOFLOW_SANITIZE "" CACHE STRING "Sanitizers to build with (e.g. address,undefined); empty: none")
if(GEOFLOW_SANITIZE)
  set(_geoflow_sanitize_flags -fsanitize=${GEOFLOW_SANITIZE} -fsanitize=float-cast-overflow
      -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_options(${_geoflow_sanitize_flags})
  add_link_options(${_geoflow_sanitize_flags})
  # The runtime options every test (and every program a test starts) runs with; see
  # tests/sanitizers/README.md for the suppressions and their reasons.
  set(GEOFLOW_SANITIZER_ENVIRONMENT
      "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1"
      "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/sanitizers/lsan.supp:print_suppressions=0")
endif()
