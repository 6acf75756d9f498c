// error: 4:10 `/etc/passwd` is outside the folders scenes may read and write
// error-text: data files must be in

#fopen F "/etc/passwd" read
