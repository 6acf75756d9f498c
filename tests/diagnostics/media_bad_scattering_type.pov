// error: 6:35 scattering type must be 1 to 5
// error-text: Henyey-Greenstein

// A scattering type outside 1..5.
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { scattering { 7, rgb 0.1 } } }
}
