// error: 6:3 nesting deeper than
// error-text: in macro `Deep`
// error-text: times)

#macro Deep(N)
  Deep(N + 1)
#end
#declare X = Deep(0);
