// TODO(x): y
//@solution
//@end
//@stub
not a stub
//@end
//@bogus
