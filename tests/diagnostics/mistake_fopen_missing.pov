// error: 5:13 cannot open `
// error-text: no_such_data.txt` for reading
// POV-Ray: Parse Error: Cannot open user file no_such_data.txt (read).
// Mistake: `#fopen` of a file that does not exist
#fopen Data "no_such_data.txt" read
