// TODO(01.a): do it
// Checked by: raylab check --stage 01
//@solution
return hit;
//@stub
//@ labTodo();
//@
  //@ return NO_HIT;
//@end
