# Basis Universal's transcoder (third_party/basisu, 1.16.4) as a static library named NAME: KTX2 textures
# (KHR_texture_basisu), transcoded to RGBA only, so every GPU block format's tables are left out; Zstandard from
# Debian's libzstd. Used by host/CMakeLists.txt and by the fuzzers' build (tools/fuzz), which adds its sanitizers.
function(vkmc_basisu_library name root)
  add_library(${name} STATIC ${root}/third_party/basisu/basisu_transcoder.cpp)
  target_include_directories(${name} SYSTEM PUBLIC ${root}/third_party/basisu)
  target_compile_definitions(${name} PUBLIC BASISD_SUPPORT_KTX2=1 BASISD_SUPPORT_KTX2_ZSTD=1 BASISD_SUPPORT_UASTC=1
    BASISD_SUPPORT_DXT1=0 BASISD_SUPPORT_DXT5A=0 BASISD_SUPPORT_BC7_MODE5=0 BASISD_SUPPORT_PVRTC1=0
    BASISD_SUPPORT_ETC2_EAC_A8=0 BASISD_SUPPORT_ASTC=0 BASISD_SUPPORT_ATC=0 BASISD_SUPPORT_ETC2_EAC_RG11=0
    BASISD_SUPPORT_FXT1=0 BASISD_SUPPORT_PVRTC2=0 BASISU_SUPPORT_SSE=0)
  target_compile_options(${name} PRIVATE -w)
  target_link_libraries(${name} PUBLIC zstd)
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
