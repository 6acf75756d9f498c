// error: 4:1 the file policy does not allow scenes to read `/etc/passwd`
// error-text: the file policy lets scenes read only in

#include "/etc/passwd"
