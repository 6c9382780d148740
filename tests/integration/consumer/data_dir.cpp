// The package's Antumbra_DATA_DIR, alone in this file: only it recompiles when the prefix
// moves.
const char* antumbra_data_dir() {
  return ANTUMBRA_DATA_DIR;
}
