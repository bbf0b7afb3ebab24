# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).

# Similarity properties of PRCS, PRRS, ringed surfaces and inversions
# through the C ABI (SPEC §9b.4).
cyclide_hardening_test(test_hardening_canal_similarity_surfaces
  SOURCES canal_similarity_surfaces_test.cpp
  LABELS property;canal C_API PROPERTY)

# Similarity properties of the canal, ringed, P-curve and n-way blends.
cyclide_hardening_test(test_hardening_canal_similarity_blends
  SOURCES canal_similarity_blends_test.cpp
  LABELS property;canal;blend C_API PROPERTY)
