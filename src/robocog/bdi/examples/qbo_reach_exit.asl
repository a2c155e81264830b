// The Q.bo robot leaving a room: the plans of Figs. 6-8 of Fujita et al. (2014),
// as printed there, followed by the sub-goals the paper does not give.
//
// The figures are typeset with "--" where the paper's text names the belief-revision
// operator "-+" ("The symbol '-+' denotes a belief revision"); "-+" is written here.
// Environment actions: looking_Qbo(Object), and forward_Qbo(Dir) / search_Qbo(Dir) sent
// through tcp_write(...). Percepts: my_current_direction(D), found_obstacle,
// found_target(Object), target_direction(D), front_of(Object).

// ---- Fig. 6 Plan for finding exit of room
@re
+!reach_exit
<- // access the door
    !reach_object(door);
    // find the entrance
    !reach_object(entry).

// ---- Fig. 7 Sub-plans for finding object
@ro
+!reach_object(Object)
<- // initially set approximate
    // direction to object
    !set_expected_target_direction(Object);
    // main process of search
    !search_object(Object).

@s_td1
+!set_expected_target_direction(door)
<- // set expected direction
    // of door given ad hoc
    -+expected_target_direction(0).

@s_td2
+!set_expected_target_direction(entry)
: my_current_direction(Dir)
<- // expected direction of door entry
    // is separated by 45 degrees from
    // current direction
    -+expected_target_direction(Dir + 45).

@so1
+!search_object(Object)
: // if not in front of object yet
    not front_of(Object)
<- // receive perception caused by
    // previous action
    !get_my_current_direction;
    !get_information_of_obstacle;
    // internally call looking_Qbo to
    // find target object
    !around_search(Object);
    // decide next action and
    // send it to robot
    !decide_action;
    // recursively try to achieve the goal
    !search_object(Object).

@so2
+!search_object(Object)
<- true. // if already in front of object

// ---- Fig. 8 Sub-plans for deciding action
@da1
+!decide_action
: // if target is visible, and
  // facing obstacle
  found_target(Object) &
  target_direction(Dir) &
  found_obstacle
<- // find nearest direction
  // with no obstacle
  tcp_write(search_Qbo(Dir)).

@da2
+!decide_action
: // if target is visible, and
  // not facing obstacle
  found_target(Object) &
  target_direction(Dir)
<- // proceed toward the target
  tcp_write(forward_Qbo(Dir)).

@da3
+!decide_action
: // if target is not visible, and
  // facing obstacle
  found_obstacle &
  // expected_target_direction/1
  // returns approximate direction of
  // the target given initially
  expected_target_direction(Dir)
<- // find direction with no obstacle
  // near initial direction
  tcp_write(search_Qbo(Dir)).

@da4
+!decide_action
: // if target is not visible,
  // nor facing obstacle
  expected_target_direction(Dir)
<- // proceed toward initial direction
  tcp_write(forward_Qbo(Dir)).

// ---- Not given in the paper ("not all definitions of sub-goals are given"):
// the direction and the obstacle arrive as percepts after each action, and looking
// around is the looking_Qbo action, whose result is perceived as found_target/1 and
// target_direction/1.
@gd
+!get_my_current_direction <- true.
@go
+!get_information_of_obstacle <- true.
@as
+!around_search(Object) <- looking_Qbo(Object).
