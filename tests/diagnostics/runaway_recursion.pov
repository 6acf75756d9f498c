#macro Deep(N)
  Deep(N + 1)
#end
#declare X = Deep(0);
