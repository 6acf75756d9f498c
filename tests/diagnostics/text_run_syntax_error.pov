// error: 7:14 in the text this file produced: unmatched `]`
// error-text: remove it, or add the `[` it should close

// The braces cross the #if branches, so the file runs token by token; a mistake later in
// it is still reported where it was written.
#if (1) union { #else merge { #end
  box { 0, 1 ] }
}
