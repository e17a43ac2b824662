#include "../etc/passwd"
