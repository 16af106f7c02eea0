# Install/uninstall package REINFORCE (fix reinforce/invert) for LAMMPS's
# traditional make: `make yes-reinforce` / `make no-reinforce` in src/.
# mode = 0/1/2 for uninstall/install/update

mode=$1
LC_ALL=C
export LC_ALL

action () {
  if (test $mode = 0) then
    rm -f ../$1
  elif (! cmp -s $1 ../$1) then
    cp $1 ..
    if (test $mode = 2) then
      echo "  updating src/$1"
    fi
  fi
}

for file in *.cpp *.h; do
  test -f ${file} && action $file
done

# The engine needs C++17: added to PKG_INC, which follows CCFLAGS.
if (test $mode = 1) then
  if (test -e ../Makefile.package) then
    sed -i -e 's/-std=c++17 //' ../Makefile.package
    sed -i -e 's|^PKG_INC =[ \t]*|&-std=c++17 |' ../Makefile.package
  fi
elif (test $mode = 0) then
  if (test -e ../Makefile.package) then
    sed -i -e 's/-std=c++17 //' ../Makefile.package
  fi
fi
