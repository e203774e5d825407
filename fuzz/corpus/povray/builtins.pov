#version 3.7;
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#debug concat(str(abs(-2.5),0,4)," ",str(acos(0.5),0,6)," ",str(asin(0.5),0,6)," ",str(atan2(1,2),0,6)," ",str(ceil(1.2),0,1)," ",str(floor(-1.2),0,1),"\n")
#debug concat(str(degrees(1),0,6)," ",str(radians(90),0,6)," ",str(exp(1),0,6)," ",str(ln(10),0,6)," ",str(log(1000),0,6)," ",str(sqrt(2),0,6),"\n")
#debug concat(str(max(1,5,3),0,0)," ",str(min(4,2,8),0,0)," ",str(select(-1,10,20),0,0)," ",str(select(0,10,20,30),0,0)," ",str(bitwise_and(12,10),0,0)," ",str(bitwise_or(12,10),0,0)," ",str(bitwise_xor(12,10),0,0),"\n")
#debug concat(str(vlength(<3,4,0>),0,3)," ",vstr(3,vnormalize(<3,0,4>),",",0,3)," ",str(vdot(<1,2,3>,<4,5,6>),0,1)," ",vstr(3,vcross(x,y),",",0,1),"\n")
#debug concat(vstr(3,vrotate(<1,0,0>,<0,0,90>),",",0,4)," ",vstr(3,vrotate(<1,2,3>,<30,40,50>),",",0,4)," ",vstr(3,vaxis_rotate(<1,0,0>,<0,1,0>,90),",",0,4),"\n")
#debug concat(chr(65),substr("hello",2,3),strupr("abc"),strlwr("DEF")," ",str(strlen("hello"),0,0)," ",str(asc("A"),0,0)," ",str(val("2.5"),0,2)," ",str(strcmp("a","b"),0,0),"\n")
#debug concat(str(dimensions(A),0,0)," ",str(dimension_size(A,2),0,0)," ",str(A[1][2],0,0)," ",str(defined(A),0,0)," ",str(defined(Nope),0,0),"\n")
#declare F = function(a, b) { a*b + 1 }
#debug concat(str(F(3,4),0,0)," ",str((2 > 1) + (1 >= 1) + (1 != 1) + (1 = 1),0,0)," ",str(!0,0,0)," ",str(<1,2,3>.y,0,0)," ",str(pi,0,8),"\n")
#for (I, 1, 10, 3) #debug str(I,0,0) #end #debug "\n"
#declare I = 0; #while (I < 3) #declare I = I + 1; #if (I = 2) #debug "two" #elseif (I = 3) #debug "three" #else #debug "one" #end #end #debug "\n"
#ifdef (A) #debug "A" #end #ifndef (B) #debug "noB" #end #debug "\n"
#debug concat(str(tan(1),0,6), " ", str(sinh(1),0,6), " ", str(cosh(1),0,6), " ", str(tanh(1),0,6), " ", str(asinh(1),0,6), " ", str(acosh(2),0,6), " ", str(atanh(0.5),0,6), " ", str(atan(1),0,6), "\n")
#debug concat(str(version,0,1), " ", str(int(3.7),0,0), " ", str(clock,0,0), " ", str(clock_delta,0,0), " ", str(initial_frame,0,0), " ", str(final_frame,0,0), "\n")
#declare C = rgbft <0.1,0.2,0.3,0.4,0.5>; #debug concat(str(C.red,0,1), str(C.green,0,1), str(C.blue,0,1), str(C.filter,0,1), str(C.transmit,0,1), " ", str(C.gray,0,4), "\n")
#declare D = color red 1 green 0.5 blue 0.25 transmit 0.5; #debug concat(vstr(5,D,",",0,2),"\n")
#declare E = <1,2,3>*2 - <1,1,1>/2; #debug concat(vstr(3,E,",",0,2),"\n")
#declare G = rgbt <1,0,0,0.5> * 0.5; #debug concat(vstr(5,G,",",0,2),"\n")
