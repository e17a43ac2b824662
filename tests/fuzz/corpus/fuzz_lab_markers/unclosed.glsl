// TODO(x): y
//@solution
x
//@stub
//@ y
