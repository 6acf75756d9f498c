// error: 6:14 unknown member `.gren`
// error-text: members are .x .y .z .t .u .v .red .green .blue .filter .transmit .gray
// POV-Ray: Parse Error: Expected 'x, y, z or color component', undeclared identifier 'gren' found instead
// Mistake: colour component `.green` misspelt `.gren`
#declare Col = rgb <1, 0.5, 0>;
#declare G = Col.gren;
