# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).
cyclide_hardening_test(test_hardening_lie SOURCES lie_inputs_test.cpp LABELS lie;capi C_API)
