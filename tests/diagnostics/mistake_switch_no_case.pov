// error: 7:3 `#switch` must start with `#case` or `#range`
// error-text: put `#case (Value)` or `#range (Low, High)` before the content of each branch
// POV-Ray: Parse Error: #switch not followed by #case or #range.
// Mistake: content before the first `#case` of a `#switch`
#declare A = 1;
#switch (A)
  sphere { 0, 1 }
#end
