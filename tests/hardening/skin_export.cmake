# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).
cyclide_hardening_test(test_hardening_export_inputs SOURCES export_inputs_test.cpp
                       LABELS export;skin;capi C_API)
if(CYCLIDE_HAVE_CERES)
  cyclide_hardening_test(test_hardening_optim_inputs SOURCES optim_inputs_test.cpp
                         LABELS optim;capi C_API)
endif()

# Similarity properties of sphere skins, the exact export, the tessellation
# and the bump optimizer's boxes (SPEC §9b.4).
cyclide_hardening_test(test_hardening_skin_similarity SOURCES skin_similarity_test.cpp
                       LABELS property;skin;export C_API PROPERTY)
