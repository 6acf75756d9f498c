// error: 5:14 unterminated string
// error-text: this string runs over 2 lines to the end of the file
// POV-Ray: Parse Error: No end quote for string.
// Mistake: string without its closing quote
#declare S = "hello;
sphere { 0, 1 }
