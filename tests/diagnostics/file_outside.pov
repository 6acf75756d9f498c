// error: 4:10 the file policy does not allow scenes to read `/etc/passwd`
// error-text: --allow-read /etc

#fopen F "/etc/passwd" read
