#version 3.7;
#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end
#declare A = array[2][2] { {1, 2}, {3, F(4)} };
#switch (A[1][1]) #case (24) #debug "yes" #break #else #debug "no" #end
#for (I, 0, 3) sphere { <I, 0, 0>, 0.5 } #end
