// error: 6:12 unknown fog_type 3
// error-text: expected 1 (constant) or 2 (ground fog)

fog {
  distance 10
  fog_type 3
}
