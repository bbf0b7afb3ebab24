# cyclide_hardening_test(...) entries of this family (see CMakeLists.txt).
