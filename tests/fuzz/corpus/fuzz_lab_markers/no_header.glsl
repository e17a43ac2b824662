//@solution
x
//@end
