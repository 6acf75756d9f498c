// error: 10:1 `#elseif` after `#else`
// error-text: put every `#elseif` before the `#else`
// POV-Ray: Parse Error: Mis-matched '#elseif'.
// Mistake: `#elseif` after `#else`
#declare A = 1;
#if (A = 0)
  sphere { 0, 1 }
#else
  box { 0, 1 }
#elseif (A = 1)
  torus { 1, 0.2 }
#end
