# cyclide_hardening_test(...) entries of the canal families' C ABI (see
# CMakeLists.txt): counts, double inputs, messages and outputs of the entry
# points of cyclide_c, blend_c, ringed_c, implicit_c and nway_c.
cyclide_hardening_test(test_hardening_canal_capi
  SOURCES canal_capi_validation_test.cpp
  LABELS canal capi
  C_API)
