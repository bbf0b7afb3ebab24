# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).
cyclide_hardening_test(test_hardening_lie SOURCES lie_inputs_test.cpp LABELS lie;capi C_API)
cyclide_hardening_test(test_hardening_lie_similarity SOURCES lie_similarity_test.cpp
                       LABELS lie;property C_API PROPERTY)
cyclide_hardening_test(test_hardening_lie_frames SOURCES lie_frames_test.cpp LABELS lie;capi C_API)
