# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).
cyclide_hardening_test(test_hardening_laguerre_sizes SOURCES laguerre_sizes_test.cpp
                       LABELS laguerre;capi C_API)
cyclide_hardening_test(test_hardening_laguerre_inputs SOURCES laguerre_inputs_test.cpp
                       LABELS laguerre;capi C_API)
cyclide_hardening_test(test_hardening_laguerre_similarity SOURCES laguerre_similarity_test.cpp
                       LABELS laguerre;property C_API PROPERTY)
