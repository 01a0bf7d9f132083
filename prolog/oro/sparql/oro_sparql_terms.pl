:- module(oro_sparql_terms,
          [ value_class/2,              % +Term, -Class
            order_class/3,              % +ClassA, +ClassB, -Order
            term_order/3,               % +A, +B, -Order
            datetime_order/5,           % +X, +ZX, +Y, +ZY, -Order
            lexical_atom/2,             % +Term, -Lexical
            lexical_number/3,           % +Kind, +Lex, -N
            boolean_lexical/2,          % ?Lex, ?Boolean
            date_stamp/2,               % +Lex, -Stamp
            xsd_date_time//0,
            date_type/1,                % ?Type
            xsd_string/1,               % ?Type
            xsd_boolean/1,              % ?Type
            lookup/4                    % +Name, +Mu, +Ctx, -Value
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(date)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/sparql/oro_sparql_lexer), [digits//1]).

/** <module> SPARQL term values: XSD lexical spaces, comparison, order

What the evaluator (oro_sparql_eval) and the expressions
(oro_sparql_functions) both need of RDF terms: the value of a literal
for comparisons (numbers, strings, booleans, dates and times, read from
the XSD lexical spaces), the order of two values, the ORDER BY order of
any two terms, and the value of a variable in a solution.
*/

:- rdf_meta
    xsd_string(r),
    xsd_boolean(r),
    date_type(r).

		 /*******************************
		 *           DATATYPES          *
		 *******************************/

%!  date_type(?Type) is nondet.
%
%   Type is an XSD date or time datatype SPARQL compares by value.

date_type(xsd:dateTime).
date_type(xsd:date).

%!  xsd_string(?Type) is semidet.
%!  xsd_boolean(?Type) is semidet.
%
%   Type is xsd:string, xsd:boolean.

xsd_string(xsd:string).
xsd_boolean(xsd:boolean).

		 /*******************************
		 *            VALUES            *
		 *******************************/

%!  value_class(+Term, -Class) is semidet.
%
%   Class is the value of the literal Term for comparisons:
%   number(Kind, N), string(S, Lang), boolean(B), datetime(Type, T,
%   Zoned) (T the time stamp, a value without time zone read as UTC,
%   Zoned true or false; an xsd:dateTime and an xsd:date are not
%   comparable), ...

value_class(literal(V), C) :-
    !,
    literal_class(V, C).
value_class(X, C) :-
    atom(X),
    (   rdf_is_bnode(X)
    ->  C = bnode(X)
    ;   C = iri(X)
    ).

literal_class(type(T, Lex0), C) :-
    !,
    lexical_atom(Lex0, Lex),
    (   oro_numeric_datatype(T, Kind)
    ->  (   lexical_number(Kind, Lex, N)
        ->  C = number(Kind, N)
        ;   C = invalid(T, Lex)
        )
    ;   xsd_string(T)
    ->  C = string(Lex, xsd)
    ;   xsd_boolean(T)
    ->  (   boolean_lexical(Lex, B)
        ->  C = boolean(B)
        ;   C = invalid(T, Lex)
        )
    ;   date_type(T)
    ->  (   date_value(T, Lex, Stamp, Zoned)
        ->  C = datetime(T, Stamp, Zoned)
        ;   C = invalid(T, Lex)
        )
    ;   C = typed(T, Lex)
    ).
literal_class(lang(Tag, Lex0), lang(Lex, Tag)) :-
    !,
    lexical_atom(Lex0, Lex).
literal_class(Lex0, string(Lex, simple)) :-
    lexical_atom(Lex0, Lex).

%!  lexical_atom(+Term, -Lexical) is det.
%
%   Lexical is the lexical form of the literal Term.

lexical_atom(X, A) :-
    (   atom(X)
    ->  A = X
    ;   format(atom(A), '~w', [X])
    ).

%!  date_stamp(+Lex, -Stamp) is semidet.
%
%   Stamp is the time stamp of the xsd:dateTime or xsd:date Lex; 24:00:00 is midnight of the next day (XSD 1.1).

date_stamp(Lex, Stamp) :-
    (   sub_atom(Lex, B, _, A, 'T24:00:00')
    ->  sub_atom(Lex, 0, B, _, Day),
        sub_atom(Lex, _, A, 0, Rest),
        atomic_list_concat([Day, 'T00:00:00', Rest], Lex1),
        catch(parse_time(Lex1, iso_8601, Stamp0), _, fail),
        Stamp is Stamp0 + 86400
    ;   catch(parse_time(Lex, iso_8601, Stamp), _, fail)
    ).

%!  xsd_date_time// is semidet.
%
%   The lexical space of xsd:dateTime,
%   -?YYYY-MM-DDThh:mm:ss(.s+)?(Z|(+|-)hh:mm)?

xsd_date_time -->
    optional_minus,
    digits(Y), { length(Y, NY), NY >= 4 },
    "-", two_digits, "-", two_digits, "T",
    two_digits, ":", two_digits, ":", two_digits,
    optional_fraction,
    optional_zone.

optional_minus --> "-", !.
optional_minus --> [].

two_digits --> [A, B], { code_type(A, digit), code_type(B, digit) }.

optional_fraction --> ".", !, digits([_|_]).
optional_fraction --> [].

optional_zone --> "Z", !.
optional_zone --> [S], { S == 0'+ ; S == 0'- }, !,
    two_digits, ":", two_digits.
optional_zone --> [].

%   date_value(+Type, +Lex, -Stamp, -Zoned): the value of an xsd:date
%   (midnight starting the day, in its time zone if it has one) or
%   xsd:dateTime.

date_value(Type, Lex, Stamp, Zoned) :-
    (   rdf_equal(Type, xsd:date)
    ->  sub_atom(Lex, B, 1, _, '-'),
        B > 0,
        sub_atom(Lex, 0, B, _, Year),
        Start is B + 6,
        sub_atom(Lex, 0, Start, After, Day),
        sub_atom(Lex, Start, After, 0, Zone),
        atom_length(Year, YL), YL >= 4,
        atomic_list_concat([Day, 'T00:00:00', Zone], DateTime)
    ;   DateTime = Lex
    ),
    date_stamp(DateTime, Stamp),
    (   time_zoned(DateTime)
    ->  Zoned = true
    ;   Zoned = false
    ).

time_zoned(Lex) :-
    (   sub_atom(Lex, _, 1, 0, 'Z')
    ->  true
    ;   sub_atom(Lex, B, 6, 0, Zone),
        B >= 19,
        sub_atom(Zone, 0, 1, _, Sign),
        memberchk(Sign, ['+', '-']),
        sub_atom(Zone, 3, 1, _, ':')
    ).

%!  datetime_order(+X, +ZX, +Y, +ZY, -Order) is semidet.
%
%   Order is XSD's order of the date and
%   time values: a value without time zone is any time from 14 hours
%   before to 14 hours after the same time in UTC, so it is ordered
%   against a zoned value only when the whole range is on one side
%   (fails otherwise: indeterminate).

datetime_order(X, Z, Y, Z, O) :-
    !,
    number_order(X, Y, O).
datetime_order(X, false, Y, true, O) :-
    !,
    Span = 50400,
    (   X + Span < Y
    ->  O = (<)
    ;   X - Span > Y
    ->  O = (>)
    ).
datetime_order(X, true, Y, false, O) :-
    datetime_order(Y, false, X, true, O0),
    inverse_order(O0, O).

inverse_order(<, >).
inverse_order(>, <).

%!  boolean_lexical(?Lex, ?Boolean) is nondet.
%
%   Lex is a lexical form of the xsd:boolean Boolean.

boolean_lexical(true, true).
boolean_lexical(false, false).
boolean_lexical('1', true).
boolean_lexical('0', false).

%!  lexical_number(+Kind, +Lex, -N) is semidet.
%
%   N is the number of the XSD lexical form Lex of the numeric Kind.

lexical_number(integer, Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_integer, Codes0),
    strip_plus(Codes0, Codes),
    number_codes(N, Codes).
lexical_number(decimal, Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_decimal, Codes0),
    strip_plus(Codes0, Codes1),
    decimal_codes(Codes1, Codes),
    decimal_rational(Codes, N).

lexical_number(float, Lex, N) :-
    lexical_double(Lex, N).
lexical_number(double, Lex, N) :-
    lexical_double(Lex, N).

%   decimal_rational(+Codes, -N): xsd:decimal values are exact: N is
%   an integer or a rational number (1.1 is 11r10), so that sums and
%   products of decimals are exact as XSD requires.

decimal_rational(Codes, N) :-
    (   Codes = [0'-|Abs]
    ->  decimal_rational(Abs, N0),
        N is -N0
    ;   append(Int, [0'.|Frac], Codes)
    ->  append(Int, Frac, Digits),
        number_codes(Whole, Digits),
        length(Frac, Scale),
        N is Whole rdiv 10^Scale
    ;   number_codes(N, Codes)
    ).
lexical_double('INF', N) :- !, N is inf.
lexical_double('+INF', N) :- !, N is inf.
lexical_double('-INF', N) :- !, N is -inf.
lexical_double('NaN', N) :- !, N is nan.
lexical_double(Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_double, Codes0),
    strip_plus(Codes0, Codes1),
    decimal_codes(Codes1, Codes),
    number_codes(N0, Codes),
    N is float(N0).

strip_plus([0'+|Cs], Cs) :- !.
strip_plus(Cs, Cs).

%   The lexical spaces of xsd:integer, xsd:decimal and xsd:double.

xsd_integer --> xsd_sign, digits(D), { D \== [] }.

xsd_decimal -->
    xsd_sign,
    digits(I),
    (   "."
    ->  digits(F),
        { I \== [] ; F \== [] }
    ;   { I \== [] }
    ).

xsd_double -->
    xsd_decimal,
    (   [E], { E == 0'e ; E == 0'E }
    ->  xsd_sign,
        digits(D),
        { D \== [] }
    ;   []
    ).

xsd_sign --> "+", !.
xsd_sign --> "-", !.
xsd_sign --> [].

%   decimal_codes(+Codes0, -Codes): make `.5`, `5.` and `5.e3` readable
%   by number_codes/2.

decimal_codes(Codes0, Codes) :-
    (   Codes0 = [0'-|Rest]
    ->  decimal_codes(Rest, Codes1),
        Codes = [0'-|Codes1]
    ;   Codes0 = [0'.|_]
    ->  decimal_codes([0'0|Codes0], Codes)
    ;   append(Int, [0'.|Frac], Codes0)
    ->  (   ( Frac == [] ; Frac = [E|_], memberchk(E, `eE`) )
        ->  append(Int, [0'., 0'0|Frac], Codes)
        ;   Codes = Codes0
        )
    ;   Codes = Codes0
    ),
    Codes \== [],
    Codes \== `-`.

		 /*******************************
		 *            ORDER             *
		 *******************************/

%!  order_class(+ClassA, +ClassB, -Order) is semidet.
%
%   Order compares two values of value_class/2; fails when they are not
%   comparable.

order_class(number(_, X), number(_, Y), O) :- !, number_order(X, Y, O).
order_class(string(X, _), string(Y, _), O) :- !, compare(O, X, Y).
order_class(boolean(X), boolean(Y), O) :- !, compare(O, X, Y).
order_class(datetime(T, X, ZX), datetime(T, Y, ZY), O) :-
    !,
    datetime_order(X, ZX, Y, ZY, O).

number_order(X, Y, O) :-
    (   X < Y
    ->  O = (<)
    ;   X > Y
    ->  O = (>)
    ;   X =:= Y
    ->  O = (=)
    ).

%!  term_order(+A, +B, -Order) is det.
%
%   Order is the ORDER BY order of the RDF terms A and B: unbound <
%   blank nodes < IRIs < literals; literals by value when comparable.

term_order(A, B, Order) :-
    term_rank(A, RA),
    term_rank(B, RB),
    (   RA =\= RB
    ->  compare(Order, RA, RB)
    ;   RA =:= 3,
        value_class(A, CA),
        value_class(B, CB),
        order_class(CA, CB, O0),
        O0 \== (=)
    ->  Order = O0
    ;   compare(Order, A, B)
    ).

term_rank('$unbound', 0) :- !.
term_rank(literal(_), 3) :- !.
term_rank(X, 1) :- rdf_is_bnode(X), !.
term_rank(_, 2).

		 /*******************************
		 *          SOLUTIONS           *
		 *******************************/

%!  lookup(+Name, +Mu, +Ctx, -Value) is semidet.
%
%   Value is the value of the variable Name in the solution Mu or in
%   the substitution of Ctx (EXISTS).

lookup(N, Mu, ctx(_, Subst, _, _), V) :-
    (   memberchk(N-V0, Mu)
    ->  V = V0
    ;   memberchk(N-V0, Subst)
    ->  V = V0
    ).
