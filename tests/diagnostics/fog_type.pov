fog {
  distance 10
  fog_type 3
}
