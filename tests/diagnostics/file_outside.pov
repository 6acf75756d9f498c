#fopen F "/etc/passwd" read
