#include <cstdint>
#include <cstddef>
extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t);
int main(){ return LLVMFuzzerTestOneInput(nullptr,0); }
