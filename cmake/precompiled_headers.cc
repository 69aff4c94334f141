// Compiled only for the precompiled headers of target fsgmpm_pch (see
// CMakeLists.txt), which the programs linked to the library reuse.
