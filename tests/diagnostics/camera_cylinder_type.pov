camera {
  cylinder 5
  location <0, 1, -3>
}
