// Where the installed package keeps its graphs and shaders: Antumbra_DATA_DIR, compiled in by
// CMakeLists.txt. A file of its own, so that a prefix moved elsewhere rebuilds this alone.
const char* antumbra_data_dir() {
  return HOST_ANTUMBRA_DATA;
}
