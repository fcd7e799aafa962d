/* Stands in for ICU's 30 MB data library in the GPU bundle (make_bundle.sh):
   Mesa's LLVM loads libxml2, which loads ICU, and no text is converted.
   ICU_DATA is the symbol of this ICU version's data, icudt<version>_dat. */
const char ICU_DATA[256] __attribute__((aligned(16))) = { 0 };
