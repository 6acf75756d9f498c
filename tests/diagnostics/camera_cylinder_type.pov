// error: 5:12 unknown cylinder camera type 5
// error-text: expected 1, 2, 3 or 4

camera {
  cylinder 5
  location <0, 1, -3>
}
